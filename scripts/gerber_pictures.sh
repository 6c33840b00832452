#!/usr/bin/env bash
# The pictures of README.md's gerber2deck section: a real board's copper
# layer and what the 1977 chain draws of it (gerber2deck -> tenzor -> em703
# gerber), both rendered by gerbv on the same window at 0.05 mm a pixel.
# Needs $REALBOARDS (the folder of the real boards) and `make build`.
#   bash scripts/gerber_pictures.sh      writes docs/img/gerber-*.png
set -euo pipefail
cd "$(dirname "$0")/.."
: "${REALBOARDS:?set REALBOARDS to the folder of the real boards}"
export PATH=$PWD/.venv/bin:$PATH
tenzor="$(fpm run --runner echo tenzor 2>/dev/null | tail -n 1)"
em703="$(fpm run --runner echo em703 2>/dev/null | tail -n 1)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
board=$REALBOARDS/geda-stepper-driver
gerber2deck "$board/driver.top.gbr" --drill "$board/driver.plated-drill.cnc" \
    -o "$work/board.crd" 2>"$work/report.txt"
# the start point's place on the board (the deck's coordinates are from it)
read -r ox oy < <(sed -n 's/.*start point at board \([-0-9.]*\), \([-0-9.]*\) mm.*/\1 \2/p' "$work/report.txt")
"$tenzor" "$work/board.crd" -o "$work/tapes" >/dev/null
"$em703" gerber "$work/tapes/DRIVER_TOP.job" -o "$work/mask.gbr"
render() {   # render GERBER X0 Y0 OUT.png: a 45 x 70 mm window from X0, Y0 mm
    gerbv -a -x png -u mm -D 508 --origin="$2x$3" -w 900x1400 -B 0 -b '#ffffff' -f '#b87333ff' \
        -o "$4" "$1"
}
render "$board/driver.top.gbr" "$(python -c "print(f'{$ox - 1:.4f}')")" "$(python -c "print(f'{$oy - 1:.4f}')")" \
    docs/img/gerber-geda-original.png
render "$work/mask.gbr" -1.0000 -1.0000 docs/img/gerber-geda-roundtrip.png
echo "docs/img/gerber-geda-original.png docs/img/gerber-geda-roundtrip.png"
