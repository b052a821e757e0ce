# Two entry points (see README): `make figures` rebuilds every result, `make test` runs the test suite.
# Both create the virtual environment .venv and install exactly the lock (requirements/lock.txt: every
# package pinned with its hashes, one file for every supported Python) plus the project itself first.

PYTHON ?= python3
VENV := .venv
BIN := $(abspath $(VENV))/bin
STAMP := $(VENV)/.installed
LOCK := requirements/lock.txt
UV_LOCK := requirements/uv.txt
JOBS ?= 2
# Snakemake's default (ILP) scheduler starts an LP solver at every scheduling round: ~28 s of CPU and ~15 s
# of wall time in a clean build of this DAG on 2 cores (docs/TIMING.md). The greedy one picks by priority
# (longest jobs first, workflow/rules/common.smk), which is all a 2-core run needs.
SNAKEMAKE = $(BIN)/snakemake --scheduler greedy
# Every build goes through one wrapper (src/stickslip/pipeline/build.py): one build per folder ("another build
# is running in this folder"), --rerun-incomplete after a killed build, and a result changed since its rule
# wrote it (recorded size and checksum, checked by a stat) rebuilt with what reads it.
BUILD = $(BIN)/python -m stickslip.pipeline.build
export PATH := $(BIN):$(PATH)
# uv resolves for every Python >= 3.11 at once (markers pick the right pins at install time).
COMPILE = $(BIN)/uv pip compile --quiet --universal --python-version 3.11 --generate-hashes

.PHONY: ccx setup figures small test lint bench report clean lock slurm-test repair

# A venv names the folder that built it (its scripts' #! lines, the editable install's path to src/): in a
# copied or moved project it would run the original's code, or nothing once that is gone. The stamp records
# the folder it was built for, and a venv built for another folder is built again here.
VENV_BUILT_FOR := $(shell cat $(STAMP) 2>/dev/null)
ifneq ($(VENV_BUILT_FOR),$(CURDIR))
$(STAMP): venv-elsewhere
endif
.PHONY: venv-elsewhere
venv-elsewhere:
	@echo "$(VENV) was built for '$(VENV_BUILT_FOR)', not $(CURDIR): rebuilding it"

# A fresh venv each time the lock changes, so what is installed is the lock and nothing else. Bytecode is
# compiled at install (not for the packages' own test suites): every job is a new interpreter, and where
# PYTHONDONTWRITEBYTECODE is set (as on the CI machine) each one would otherwise recompile numpy, scipy,
# xarray, matplotlib and snakemake (~5 s a start).
$(STAMP): pyproject.toml $(LOCK) $(UV_LOCK) Makefile
	rm -rf $(VENV)
	$(PYTHON) -m venv --without-pip $(VENV)
	@# The installer (uv) goes in with the interpreter's own pip when it can target another environment
	@# (pip >= 22.3): a pip inside the venv (ensurepip, ~6 s) would install nothing else.
	if $(PYTHON) -m pip --python $(BIN)/python --version >/dev/null 2>&1; then \
	    $(PYTHON) -m pip --python $(BIN)/python install --quiet --require-hashes --no-deps -r $(UV_LOCK); \
	else \
	    $(BIN)/python -m ensurepip --default-pip >/dev/null && \
	    $(BIN)/python -m pip install --quiet --require-hashes --no-deps -r $(UV_LOCK); \
	fi
	$(BIN)/uv pip install --quiet --python $(BIN)/python --require-hashes -r $(LOCK)
	$(BIN)/uv pip install --quiet --python $(BIN)/python --no-deps --no-build-isolation -e .
	@# Bytecode for everything but the packages' own test suites (a third of the files, never imported here).
	$(BIN)/python -m compileall -q -j0 -x '/tests?/' src $$($(BIN)/python -c \
	    "import sysconfig as s; print(*{s.get_path('purelib'), s.get_path('platlib')})") >/dev/null
	echo '$(CURDIR)' > $(STAMP)

# Re-resolve every dependency to its newest allowed version (then review the diff and rebuild).
lock: $(STAMP)
	$(COMPILE) pyproject.toml requirements/build.in --extra pipeline --extra test -o $(LOCK)
	$(COMPILE) requirements/uv.in -o $(UV_LOCK)

setup: $(STAMP)

# CalculiX (Debian's calculix-ccx) for the FE peer check (rule fe_peer_calculix): installed when missing and
# this is root on a Debian-like system, otherwise a stop that says how to install it.
ccx:
	@command -v ccx >/dev/null 2>&1 || { [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1 && \
	    echo "installing CalculiX (apt-get install calculix-ccx) for the FE peer check" && \
	    { apt-get install -y -qq calculix-ccx >/dev/null 2>&1 || \
	      { apt-get update -qq >/dev/null 2>&1 && apt-get install -y -qq calculix-ccx >/dev/null 2>&1; }; }; } || \
	    { echo "make figures needs CalculiX: apt-get install -y calculix-ccx (Debian/Ubuntu)"; exit 1; }

# --logger: one console line per finished job, with the time left (src/snakemake_logger_plugin_*)
figures: $(STAMP) ccx
	$(BUILD) $(SNAKEMAKE) -j$(JOBS) --logger stickslip-progress

# A configuration with overlays builds in a folder of its own, never into results/ (the full build's; a build
# of another configuration there is refused, stickslip.pipeline.results_owner). The folder links the project's
# code and config, so its results/ is all it holds: `make small` is the small CI configuration in
# build/small/results; `make small OVERLAY="config/test/*.yaml trials/mine.yaml" OVERLAY_DIR=build/mine` any
# other (TARGETS=...: only those).
OVERLAY ?= config/test/*.yaml
OVERLAY_DIR ?= build/small
OVERLAY_FILES = $(abspath $(wildcard $(OVERLAY)))
TARGETS ?=
small: $(STAMP) ccx
	@test -n "$(OVERLAY_FILES)" || { echo "OVERLAY=$(OVERLAY): no such config file"; exit 1; }
	$(BUILD) --in $(OVERLAY_DIR) $(SNAKEMAKE) -j$(JOBS) --logger stickslip-progress $(TARGETS) \
	    --configfile $(OVERLAY_FILES)

# `make figures`, and before it every dataset's own content checksum verified (all data read, not only the
# recorded checksums): a damaged one is rebuilt with everything that depends on it (`python -m
# stickslip.io.netcdf verify` lists them).
repair: $(STAMP)
	$(BUILD) --deep $(SNAKEMAKE) -j$(JOBS)

# Both cores: pytest-xdist workers (they share one small pipeline build, tests/project_run.py).
test: $(STAMP)
	$(BIN)/python -m pytest -n $(JOBS)

# Python style and formatting (ruff, configured in pyproject.toml), rules formatting (snakefmt) and Snakemake's linter.
lint: $(STAMP)
	$(BIN)/ruff check src tests workflow benchmarks
	$(BIN)/ruff format --check src tests workflow benchmarks
	$(BIN)/snakefmt --check Snakefile workflow/rules
	$(BIN)/snakemake --lint

# Self-contained HTML report: every figure captioned with its paper figure and claim statuses.
report: $(STAMP)
	$(BUILD) $(SNAKEMAKE) -j$(JOBS)
	$(SNAKEMAKE) --report results/report.html

bench: $(STAMP)
	for script in benchmarks/bench_*.py; do echo "== $$script"; $(BIN)/python $$script || exit 1; done

clean:
	rm -rf results .snakemake build

# Opt-in (root, Debian/Ubuntu): a single-node SLURM on localhost runs a small chunked map through the
# official executor plugin and the merged dataset is compared with the local run.
slurm-test: $(STAMP)
	$(BIN)/uv pip install --quiet --python $(BIN)/python -e '.[pipeline,test,slurm]'
	STICKSLIP_SLURM_TEST=1 $(BIN)/python -m pytest -q -rA tests/slurm

# Every target with one line on what it does, then the console command (docs/USAGE.md).
.PHONY: help
help:
	@echo "make targets:"
	@echo "  setup       create .venv from the lock (requirements/lock.txt), then install the project"
	@echo "  figures     rebuild every result with snakemake -j$(JOBS) (results/index.html answers the paper)"
	@echo "  small       the small CI configuration in build/small/results (OVERLAY=<files> OVERLAY_DIR=<folder>: yours)"
	@echo "  test        the whole test suite on $(JOBS) cores (incl. the claims check)"
	@echo "  lint        ruff check, ruff format --check, snakefmt --check, snakemake --lint"
	@echo "  report      the pipeline, then results/report.html (every figure captioned)"
	@echo "  bench       every benchmarks/bench_*.py"
	@echo "  repair      figures, after verifying every dataset's content checksum (reads all data)"
	@echo "  lock        re-resolve the lock to the newest allowed versions"
	@echo "  clean       remove results/, .snakemake/ and build/ (make small's folders)"
	@echo "  slurm-test  opt-in: a small chunked map through a local SLURM"
	@echo "  help        this list"
	@echo "your own scenario (after make setup): .venv/bin/stickslip --help"
	@echo "  stickslip run --mu-s 0.6 --damping 1.0 | fe --scene ... | claims --figure 2 | show FILE.nc"
