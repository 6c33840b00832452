#!/usr/bin/env bash
# usage: scripts/fpm_build.sh [fpm build options, e.g. --profile debug --flag "..."]
#
# fpm build, the test programs too, each linked again from the objects as
# they are now.
#
# fpm 0.12 links a program again only when the same run compiled one of its
# objects. `fpm build` and `fpm run` link tenzor and em703 but not the test
# programs, so after a change in src/ or legacy/, `fpm build` then `fpm test`
# (what `make test` did) compiled the change in the first run and, in the
# second, ran test programs linked before it: they passed where the same
# tests linked again failed. So the test programs of the build are removed
# first, and fpm links them again (a fraction of a second), whichever fpm
# command compiled the objects and whenever.
set -euo pipefail
cd "$(dirname "$0")/.."

# fpm names the test programs on the way (building what it must to do so); a
# failed build names none, and the build below says what failed.
programs=$(fpm test "$@" --runner echo 2>/dev/null |
           grep -E '^build/gfortran_[0-9A-F]+/test/[A-Za-z0-9_]+$' || true)
if [ -n "$programs" ]; then
    # shellcheck disable=SC2086  # one name a line, none with a blank
    rm -f $programs
fi
exec fpm build --tests "$@"
