#!/usr/bin/env bash
# usage: scripts/judges.sh f2c|flang|gfortran [bfd|gold]
#
# TENZOR built from legacy/ by a second or third compiler, into
# build/f2c/tenzor (`make f2c`) or build/flang/tenzor (`make flang`). Each is
# a judge of legacy/: a program that relied on anything gfortran adds to
# FORTRAN 77 would not compile, or would punch other bytes
# (harness/tests/legacy/test_judges.py compares every output with the
# gfortran build's). `gfortran bfd` and `gfortran gold` build it with gfortran
# as fpm does (each routine an object in a static library) and link it with
# the named linker, into build/gfortran-bfd/ or build/gfortran-gold/
# (harness/tests/legacy/test_linkers.py). Each build keeps its objects:
# shell/ (the modern side) and obj/ (legacy/).
#
#   f2c    the FORTRAN 77 to C translator of AT&T Bell Laboratories (f2c -A
#          -u), then gcc and the libf2c run-time library; the classic route
#          of the 1990s, and a strict reading of the 1978 standard
#   flang  LLVM's Fortran compiler (Debian flang-16, flang-new-16) and its
#          run-time library
#
# The shell (app/tenzor.f90) and the monitor (src/monitor/, src/base/) are
# compiled by gfortran as in the fpm build: the same command line, the same
# exit statuses, the same device code; only the 1977 programs change
# compiler. The arithmetic stays IEEE double: no fused multiply-add
# contraction (-ffp-contract=off), no fast-math.
set -euo pipefail
cd "$(dirname "$0")/.."

judge=${1:-}
linker=${2:-}
case "$judge" in
    f2c)   tools=(f2c gcc gfortran) ;;
    flang) tools=(flang-new-16 gcc gfortran) ;;
    gfortran)
        case "$linker" in
            bfd|gold) tools=(gcc gfortran "ld.$linker") ;;
            *) echo "usage: scripts/judges.sh gfortran bfd|gold" >&2; exit 2 ;;
        esac ;;
    *) echo "usage: scripts/judges.sh f2c|flang|gfortran [bfd|gold]" >&2; exit 2 ;;
esac
for tool in "${tools[@]}"; do
    command -v "$tool" >/dev/null || {
        echo "$judge build: $tool is missing (make $judge installs it)" >&2; exit 2; }
done

out=build/$judge${linker:+-$linker}
work=$out.new
# the modern sources of the tenzor program, in the order their modules need them
shell=(src/base/base_error.f90 src/base/base_os.f90 src/base/base_files.f90 src/base/base_version.f90
       src/base/base_io.f90 src/base/base_sha256.f90 src/monitor/monitor_devices.f90
       src/monitor/devices.f90 src/base/base_args.f90 app/tenzor.f90)
rm -rf "$work"
mkdir -p "$work/obj" "$work/mod" "$work/shell"

if [ "$judge" = f2c ]; then
    [ -f /usr/include/f2c.h ] || {
        echo "f2c build: f2c.h is missing: Debian package libf2c2-dev (make f2c installs it)" >&2
        exit 2; }
    # f2c passes a CHARACTER argument's length as a 32-bit "ftnlen", gfortran
    # takes a size_t: legacy/'s calls of the eight device routines are renamed
    # f2c_dv..._ and scripts/f2c_devices.c hands them on to the monitor's.
    renames=()
    for d in dvcard dvprnt dverr dvopen dvpnch dvtext dvjob dvclos; do
        renames+=("-D${d}_=f2c_${d}_")
    done
    # -fno-strict-aliasing as f2c's COMMON and EQUIVALENCE structures need;
    # -fcommon because f2c declares each COMMON block in every file that names
    # it, as a C tentative definition, which gcc 10 and later reject as
    # defined twice otherwise.
    cflags=(-O2 -ffp-contract=off -fno-strict-aliasing -fcommon -w)
    mkdir -p "$work/c"
    for src in legacy/*.f; do
        # f2c names each routine on standard error as it goes; only errors matter
        if ! log=$(f2c -A -u -d"$work/c" "$src" 2>&1); then
            echo "f2c build: f2c cannot translate $src:" >&2
            echo "$log" | grep -v '^ \{2,\}[a-z0-9_]*:$' >&2
            exit 1
        fi
    done
    for c in "$work"/c/*.c; do
        gcc "${cflags[@]}" "${renames[@]}" -c "$c" -o "$work/obj/$(basename "${c%.c}").o"
    done
    gcc "${cflags[@]}" -c scripts/f2c_devices.c -o "$work/shell/f2c_devices.o"
    # the archive, not the shared library: the program runs where libf2c2 is
    # not installed, and libf2c's own main() is never linked (the shell's is)
    runtime=(/usr/lib/"$(gcc -print-multiarch)"/libf2c.a -lm)
elif [ "$judge" = gfortran ]; then
    for src in legacy/*.f; do
        gfortran -O2 -ffixed-form -fimplicit-none -c "$src" \
            -o "$work/obj/$(basename "${src%.f}").o"
    done
    runtime=()
else
    lib=$(dirname "$(readlink -f "$(command -v flang-new-16)")")/../lib
    # one file a process, as many at once as there are processors (flang's
    # start-up is most of its time)
    export work
    printf '%s\n' legacy/*.f | xargs -P "$(nproc)" -n 1 sh -c \
        'flang-new-16 -O2 -ffp-contract=off -ffixed-form -c "$1" \
             -o "$work/obj/$(basename "${1%.f}").o"' sh
    # flang's run-time library is C++; its I/O serves only the internal WRITEs
    # of legacy/ (the shell's I/O is gfortran's)
    runtime=("$lib/libFortranRuntime.a" "$lib/libFortranDecimal.a" -lstdc++ -lm)
fi

for src in "${shell[@]}"; do
    gfortran -O2 -ffp-contract=off -J"$work/mod" -c "$src" \
        -o "$work/shell/$(basename "${src%.f90}").o"
done
gcc -O2 -c src/base/base_files.c -o "$work/shell/base_files_c.o"
if [ "$judge" = gfortran ]; then
    # legacy/ as fpm links it: a static library, each routine pulled in only
    # when something calls it
    ar rcs "$work/liblegacy.a" "$work"/obj/*.o
    gfortran -fuse-ld="$linker" -o "$work/tenzor" "$work"/shell/*.o "$work/liblegacy.a"
else
    gfortran -o "$work/tenzor" "$work"/shell/*.o "$work"/obj/*.o "${runtime[@]}"
fi
rm -rf "$out"
mv "$work" "$out"
echo "$judge${linker:+ $linker} build: $out/tenzor"
