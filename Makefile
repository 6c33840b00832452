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

demo: build
	@fpm run tenzor -- $(DECK) -o $(OUT) 2>&1 | grep -v '^\[\|^Project\|^ *$$' ; exit $${PIPESTATUS[0]}

test: build
	fpm test
	python -m pytest harness
