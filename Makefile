# The two commands of README.md. Both set up what is missing first (scripts/setup.sh).
#   make demo   punch the tapes of the bundled demo board into out/
#   make test   run every test: the Fortran tests (fpm test) and the harness (pytest)
SHELL := /bin/bash
export PATH := $(CURDIR)/.venv/bin:$(PATH)
DECK ?= examples/demo.crd
OUT ?= out

.PHONY: demo test setup build

setup:
	@bash scripts/setup.sh

build: setup
	@fpm build >/dev/null

# The built program is run directly: `fpm run` would add its own progress lines.
demo: build
	@"$$(fpm run --runner echo tenzor 2>/dev/null | tail -n 1)" $(DECK) -o $(OUT)

test: build
	fpm test
	python -m pytest harness
