#!/usr/bin/env bash
# Redraw the pictures of docs/FILLING.md from examples/filling.crd, with the
# project's own programs: TENZOR punches the tapes, em703 draws them.
#   docs/img/filling.svg             the three layers as drawn (em703 svg)
#   docs/img/filling-paths-T.svg     the tool's centre on tape T (em703 sim --svg)
# The output is byte-identical from run to run; a test checks the committed
# pictures against a fresh drawing.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/img}
mkdir -p "$out"
out=$(cd "$out" && pwd)
export PATH=$PWD/.venv/bin:$PATH
tenzor=$PWD/$(fpm run --runner echo tenzor 2>/dev/null | tail -n 1)
em703=$PWD/$(fpm run --runner echo em703 2>/dev/null | tail -n 1)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$tenzor" examples/filling.crd -o "$work" >/dev/null
# in the work directory, so that the drawings name the tapes without a path
cd "$work"
"$em703" svg FILLING.job -o "$out/filling.svg"
for t in small large cond; do
    # a hairline tool shows the path of the tool's centre
    "$em703" sim "FILLING-$t.ptp" --start 50,50 --tool 0.04 \
        --svg "$out/filling-paths-$t.svg" >/dev/null
done
