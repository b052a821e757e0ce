# Two entry points (see README): `make figures` rebuilds every result, `make test` runs the test suite.
# Both create the virtual environment .venv and install the package with everything it needs first.

PYTHON ?= python3
VENV := .venv
BIN := $(abspath $(VENV))/bin
STAMP := $(VENV)/.installed
JOBS ?= 2
export PATH := $(BIN):$(PATH)

.PHONY: setup figures test bench report clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet -e '.[pipeline,test]'
	touch $(STAMP)

setup: $(STAMP)

figures: $(STAMP)
	$(BIN)/snakemake -j$(JOBS)

test: $(STAMP)
	$(BIN)/python -m pytest

bench: $(STAMP)
	for script in benchmarks/bench_*.py; do echo "== $$script"; $(BIN)/python $$script || exit 1; done

clean:
	rm -rf results .snakemake
