# Two entry points (see README): `make figures` rebuilds every result, `make test` runs the test suite.
# Both create the virtual environment .venv and install the package with everything it needs first.

PYTHON ?= python3
VENV := .venv
BIN := $(abspath $(VENV))/bin
STAMP := $(VENV)/.installed
JOBS ?= 2
export PATH := $(BIN):$(PATH)

.PHONY: setup figures test lint bench report clean slurm-test

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet -e '.[pipeline,test]'
	touch $(STAMP)

setup: $(STAMP)

figures: $(STAMP)
	$(BIN)/snakemake -j$(JOBS)

test: $(STAMP)
	$(BIN)/python -m pytest

# Python style (ruff, configured in pyproject.toml), rules formatting (snakefmt) and Snakemake's linter.
lint: $(STAMP)
	$(BIN)/ruff check src tests workflow benchmarks
	$(BIN)/snakefmt --check Snakefile workflow/rules
	$(BIN)/snakemake --lint

# Self-contained HTML report: every figure captioned with its paper figure and claim statuses.
report: $(STAMP)
	$(BIN)/snakemake -j$(JOBS)
	$(BIN)/snakemake --report results/report.html

bench: $(STAMP)
	for script in benchmarks/bench_*.py; do echo "== $$script"; $(BIN)/python $$script || exit 1; done

clean:
	rm -rf results .snakemake

# Opt-in (root, Debian/Ubuntu): a single-node SLURM on localhost runs a small chunked map through the
# official executor plugin and the merged dataset is compared with the local run.
slurm-test: $(STAMP)
	$(BIN)/python -m pip install --quiet -e '.[pipeline,test,slurm]'
	STICKSLIP_SLURM_TEST=1 $(BIN)/python -m pytest -q -rA tests/slurm
