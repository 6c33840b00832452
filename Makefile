# The commands of README.md. Each sets up what is missing first (scripts/setup.sh).
#   make demo      punch the tapes of the bundled demo board into out/, and its page
#                  out/NAME.html (em703 html)
#   make test      run every test: the Fortran tests (fpm test), then pytest over the
#                  oracle (harness/), the neighbouring systems (seeds/) and the benchmarks'
#                  own tests (bench/)
#   make examples  punch every deck of examples/ into out/ (docs/TOOLS.md's examples)
#   make release   the build the benchmarks time (fpm's release profile, linked statically
#                  with link-time optimisation); prints the path of its tenzor
#   make bench     the benchmarks of docs/PERFORMANCE.md (8 to 20 minutes; BENCH_ARGS=--quick
#                  for the 100- and 1 000-pad boards): a table, and out/bench/bench.csv, .svg,
#                  tsplib.csv, tsplib.svg (the recorded run: bench/results/)
#   make f2c       TENZOR built from legacy/ by f2c, gcc and libf2c: build/f2c/tenzor
#   make flang     TENZOR built from legacy/ by LLVM flang (installs Debian flang-16,
#                  about 800 MB): build/flang/tenzor
#   make rs274     install LinuxCNC's rs274 interpreter (Debian linuxcnc-uspace), which
#                  make test then runs on em703's G-code
# and, for CI (.ci/run):
#   make test-checks   the Fortran tests and every test that runs tenzor or em703,
#                      again, on a build with gfortran's run-time checks (but the
#                      comparisons with other compilers and linkers, which the
#                      bounds-checked build of make test already makes)
#   make test-cpus     the raster, verify and coverage tests again with numpy's
#                      AVX-512 paths disabled, and again without AVX2 either
#   make mutants       mutation testing (scripts/mutants.py): realistic small faults in
#                      legacy/ and src/, and how many the tests catch (tens of minutes)
#   make fuzz          exploration, not a verdict: the fuzz suites with new random
#                      cases (2500 a property) against the build with run-time checks;
#                      a failure it finds becomes an @example (docs/ROBUSTNESS.md)
SHELL := /bin/bash
export PATH := $(CURDIR)/.venv/bin:$(PATH)
DECK ?= examples/demo.crd
OUT ?= out
BENCH_ARGS ?=

# gfortran's run-time checks: bounds, array temporaries, DO variables, pointers,
# recursion, bits (-fcheck=all); a trap on a floating-point invalid operation,
# division by zero or overflow; a trap on signed integer overflow (GCC's
# undefined-behaviour sanitiser, checked in line: -ftrapv, which calls libgcc for
# every integer operation, made the checked build twice as slow). fpm adds them
# to its debug profile and builds into a directory of their own;
# harness/tests/legacy/test_run_time_checks.py checks that each one trips.
CHECKS := -fcheck=all -ffpe-trap=invalid,zero,overflow \
          -fsanitize=signed-integer-overflow -fsanitize-undefined-trap-on-error

# The built program is run directly: `fpm run` would add its own progress lines.
TENZOR = "$$(fpm run --runner echo tenzor 2>/dev/null | tail -n 1)"

.PHONY: release demo examples test test-checks test-cpus fuzz mutants bench setup build f2c flang rs274

setup:
	@bash scripts/setup.sh

# (scripts/fpm_build.sh: fpm build with the test programs linked again from the
# objects as they are, whichever fpm command compiled them.)
build: setup
	@bash scripts/fpm_build.sh >/dev/null

# demo: the tapes, then for each package punched its page (em703 html: the
# tapes on an animated coordinatograph, to open in a browser).
EM703 = "$$(fpm run --runner echo em703 2>/dev/null | tail -n 1)"
demo: build
	@set -o pipefail; list=$$(mktemp); trap 'rm -f "$$list"' EXIT; \
	$(TENZOR) $(DECK) -o $(OUT) | tee "$$list"; \
	em703=$(EM703); sed -n 's/^\([^:]*\): tapes .*/\1/p' "$$list" | \
	    while read -r name; do \
	        "$$em703" html "$(OUT)/$$name.job" -o "$(OUT)/$$name.html" || exit 1; \
	        echo "$$name: page $(OUT)/$$name.html (open it in a browser)"; \
	    done

examples: build
	@tenzor=$(TENZOR); find examples -name '*.crd' | LC_ALL=C sort | \
	    while read -r deck; do "$$tenzor" "$$deck" -o $(OUT) || exit 1; done

test: build
	fpm test
	python -m pytest

test-checks: setup
	@bash scripts/fpm_build.sh --profile debug --flag "$(CHECKS)" >/dev/null
	fpm test --profile debug --flag "$(CHECKS)"
	TENZOR_EXE="$$(fpm run --profile debug --flag "$(CHECKS)" --runner echo tenzor 2>/dev/null | tail -n 1)" \
	EM703_EXE="$$(fpm run --profile debug --flag "$(CHECKS)" --runner echo em703 2>/dev/null | tail -n 1)" \
		python -m pytest -m "tenzor or em703" \
			--ignore=harness/tests/legacy/test_judges.py --ignore=harness/tests/legacy/test_linkers.py

mutants: build
	python scripts/mutants.py

FUZZ_TESTS := harness/tests/tenzor/test_fuzz_tenzor.py harness/tests/em703/test_fuzz_em703.py \
	harness/tests/legacy/test_judges.py
fuzz: setup
	@bash scripts/fpm_build.sh --profile debug --flag "$(CHECKS)" >/dev/null
	HYPOTHESIS_PROFILE=long \
	TENZOR_EXE="$$(fpm run --profile debug --flag "$(CHECKS)" --runner echo tenzor 2>/dev/null | tail -n 1)" \
	EM703_EXE="$$(fpm run --profile debug --flag "$(CHECKS)" --runner echo em703 2>/dev/null | tail -n 1)" \
		python -m pytest $(FUZZ_TESTS) --hypothesis-show-statistics

# The tests whose verdicts come from the harness's rasteriser, and the numpy
# SIMD groups each pass disables (numpy 2's names; the first test checks they
# are off). The verdicts must be the same as on the machine's own best path.
RASTER_TESTS := harness/tests/oracle/test_cpu_features.py harness/tests/oracle/test_raster.py \
	harness/tests/oracle/test_verify.py harness/tests/oracle/test_verify_large.py harness/tests/tenzor/test_layers.py \
	harness/tests/em703/test_em703_gerber.py harness/tests/docs/test_readme_verify.py \
	seeds/tests/test_seed001_dxf.py
test-cpus: build
	NPY_DISABLE_CPU_FEATURES="X86_V4 AVX512_ICL AVX512_SPR" python -m pytest -q $(RASTER_TESTS)
	NPY_DISABLE_CPU_FEATURES="X86_V3 X86_V4 AVX512_ICL AVX512_SPR" python -m pytest -q $(RASTER_TESTS)

# The other compilers of legacy/ (scripts/judges.sh); make test compares their
# tapes, listings and job sheets with the gfortran build's, byte for byte.
f2c: setup
	@bash scripts/judges.sh f2c

# (setup.sh with WITH_FLANG=1, or WITH_RS274=1 below, does the whole set-up and
# adds its package; a `setup` prerequisite would run it twice, and on a fresh
# machine apt-get update twice.)
flang:
	@WITH_FLANG=1 bash scripts/setup.sh
	@bash scripts/judges.sh flang

# LinuxCNC's G-code interpreter, the outside reader of em703's G-code
# (harness/tests/em703/test_em703_gcode.py).
rs274:
	@WITH_RS274=1 bash scripts/setup.sh
	@command -v rs274

# The release build: fpm's release profile, linked statically (no dynamic loader at
# start-up) with link-time optimisation. The same flags as bench/measure.py's
# RELEASE_FLAGS (bench/tests/test_bench.py holds them together); the tapes are the
# same as every other build's.
RELEASE_FLAGS := -flto -static
release: setup
	@fpm build --profile release --flag "$(RELEASE_FLAGS)" >/dev/null
	@fpm run --profile release --flag "$(RELEASE_FLAGS)" --runner echo tenzor 2>/dev/null | tail -n 1

# bench builds the release build of TENZOR itself, as make release does.
bench:
	@WITH_BENCH=1 bash scripts/setup.sh
	python -m bench $(BENCH_ARGS)
