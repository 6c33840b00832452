#!/usr/bin/env bash
# Set up everything the project needs, once; fast when all is already there.
#   - gfortran (Debian package) compiles the FORTRAN 77 and the modern Fortran;
#   - gerbv (Debian package) renders em703's Gerber output for a cross-check;
#   - f2c and ftnchek (Debian packages) judge the FORTRAN 77 of legacy/, and
#     f2c with gcc and libf2c (libf2c2-dev) builds TENZOR a second way;
#   - chromium and chromium-driver (Debian packages) run the page of
#     `em703 html` headless in its tests, driven by selenium (requirements.txt);
#   - with WITH_FLANG=1 (`make flang`, CI), flang-16 (Debian, about 800 MB)
#     builds TENZOR a third way;
#   - with WITH_BENCH=1 (`make bench`), the packages of requirements-bench.txt
#     (OR-Tools for the TSPLIB table, exact pins) go into .venv as well;
#   - .venv/ holds fpm and the Python packages of requirements.txt (exact pins),
#     and the project of pyproject.toml installed editable: `python -m harness`,
#     `python -m seeds`, `python -m bench` and `dxf2deck` then work anywhere.
#   - with WITH_RS274=1 (`make rs274`, CI), linuxcnc-uspace (Debian, about
#     115 packages with Tcl/Tk) brings LinuxCNC's rs274 interpreter, which
#     reads em703's G-code in a cross-check; elsewhere that check is skipped.
# Called by `make demo` and `make test`; safe to run again at any time.
set -euo pipefail
cd "$(dirname "$0")/.."

apt_packages=()
command -v gfortran >/dev/null 2>&1 || apt_packages+=(gfortran)
command -v gerbv >/dev/null 2>&1 || apt_packages+=(gerbv)
command -v f2c >/dev/null 2>&1 || apt_packages+=(f2c)
command -v ftnchek >/dev/null 2>&1 || apt_packages+=(ftnchek)
[ -f /usr/include/f2c.h ] || apt_packages+=(libf2c2-dev)
command -v chromium >/dev/null 2>&1 || apt_packages+=(chromium)
command -v chromedriver >/dev/null 2>&1 || apt_packages+=(chromium-driver)
command -v gcc >/dev/null 2>&1 || apt_packages+=(gcc)
if [ "${WITH_FLANG:-0}" = 1 ]; then
    command -v flang-new-16 >/dev/null 2>&1 || apt_packages+=(flang-16)
fi
if [ "${WITH_RS274:-0}" = 1 ]; then
    command -v rs274 >/dev/null 2>&1 || apt_packages+=(linuxcnc-uspace)
fi
python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || apt_packages+=(python3-venv)

if [ ${#apt_packages[@]} -gt 0 ]; then
    sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    echo "setup: installing Debian packages: ${apt_packages[*]}"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
        "${apt_packages[@]}" >/dev/null
fi

# Done again whenever either file changes (the stamp holds their checksum).
want=$(cat requirements.txt pyproject.toml | sha256sum | cut -d' ' -f1)
stamp=.venv/.requirements.sha256
if [ ! -x .venv/bin/python ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
    echo "setup: installing Python packages into .venv"
    python3 -m venv .venv
    .venv/bin/python -m pip install --quiet --disable-pip-version-check -r requirements.txt
    # the project itself, with the setuptools just pinned: nothing to download
    .venv/bin/python -m pip install --quiet --disable-pip-version-check \
        --no-deps --no-build-isolation --editable .
    echo "$want" > "$stamp"
fi

# The benchmarks' own packages, on request (make bench), with a stamp of their own.
if [ "${WITH_BENCH:-0}" = 1 ]; then
    want_bench=$(cat requirements-bench.txt | sha256sum | cut -d' ' -f1)
    stamp_bench=.venv/.requirements-bench.sha256
    if [ "$(cat "$stamp_bench" 2>/dev/null)" != "$want_bench" ]; then
        echo "setup: installing the benchmarks' Python packages into .venv"
        .venv/bin/python -m pip install --quiet --disable-pip-version-check \
            -r requirements-bench.txt
        echo "$want_bench" > "$stamp_bench"
    fi
fi

# fpm adds each object to its static library and never takes one out: after a
# Fortran file is moved or renamed, the old object stays in the archive and
# the link fails with "multiple definition". When the list of Fortran files
# differs from the one the build was made from, the build starts afresh.
sources=$(find legacy src app test -name '*.f' -o -name '*.f90' | LC_ALL=C sort | sha256sum | cut -d' ' -f1)
if [ -d build ] && [ "$(cat build/.sources.sha256 2>/dev/null)" != "$sources" ]; then
    echo "setup: the Fortran files changed: rebuilding from scratch"
    rm -rf build
fi
mkdir -p build && echo "$sources" > build/.sources.sha256
# Nor does fpm compile a program or test again when only a module it uses
# changed (it compares each file's own text): after any change to the
# library's sources, the objects of app/ and test/ are made again.
library=$(find legacy src -name '*.f' -o -name '*.f90' -o -name '*.c' | LC_ALL=C sort | xargs cat | sha256sum | cut -d' ' -f1)
if [ "$(cat build/.library.sha256 2>/dev/null)" != "$library" ]; then
    rm -f build/*/*/app_*.o build/*/*/test_*.o
    echo "$library" > build/.library.sha256
fi
