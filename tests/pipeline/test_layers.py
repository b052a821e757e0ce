"""The package's layers import downwards only: every package has a place in one order (LAYER_ORDER) and
imports only from its own or lower places, lazy imports in functions included (so the packages' import
graph has no loop); no science module can reach the presentation package or the pipeline's config layer,
whatever it imports lazily (the import closure of stickslip.pipeline.code_deps)."""

from pathlib import Path

import pytest

from stickslip.pipeline.code_deps import dependency_files

SRC = Path(__file__).resolve().parents[2] / "src"
PACKAGE = SRC / "stickslip"
SCIENCE = ("model", "solvers", "analysis", "fe")


@pytest.mark.parametrize(
    "path",
    sorted(p for layer in SCIENCE for p in (PACKAGE / layer).rglob("*.py")),
    ids=lambda p: str(p.relative_to(PACKAGE)),
)
def test_a_science_module_never_reaches_presentation_or_the_pipeline(path):
    reached = dependency_files([path], SRC)
    above = [
        p
        for p in reached
        if p.is_relative_to(PACKAGE / "presentation") or p.is_relative_to(PACKAGE / "pipeline")
    ]
    assert not above, (
        f"{path.relative_to(PACKAGE)} reaches {sorted(str(p.relative_to(PACKAGE)) for p in above)}"
    )


WORKFLOW = SRC.parent / "workflow" / "scripts"


@pytest.mark.parametrize("script", sorted(WORKFLOW.glob("*.py")), ids=lambda p: p.name)
def test_no_pipeline_job_reaches_the_api_or_the_command_line(script):
    """``stickslip/__init__`` loads ``simulate``/``simulate_fe`` by name; no job's code may count them (an
    edit of the command line or the API must re-run no pipeline job)."""
    reached = {p.name for p in dependency_files([script], SRC) if p.parent == PACKAGE} & {"api.py", "cli.py"}
    assert not reached, f"{script.name} reaches {sorted(reached)}"


#: Every package and top-level module of stickslip, bottom first: a module may import (at module level or
#: lazily in a function) only from its own unit or one listed before it. A unit not listed fails the test,
#: so a new package is placed on purpose. docs/ARCHITECTURE.md draws the same order.
LAYER_ORDER = (
    "_version",  # the version string
    "catalogue",  # where every result lives: imports nothing of the project
    "model",  # parameters, friction readings and laws
    "solvers",  # 1-DOF integrators: Trajectory, SolverStats
    "analysis",  # metrics, outcome, sweeps
    "fe",  # beam and continuum models
    "schema",  # the config's typed models: every key, bound and default
    "ensemble",  # the perturbation ensemble
    "io",  # netCDF, YAML, tables
    "validation",  # the friction-law and peer validations
    "claims",  # claim rows, measures, verdicts
    "studies",  # a config section in, a dataset out
    "inverse",  # the inverse study
    "pipeline",  # the config checks across sections, the build
    "presentation",  # plots, notebooks' helpers, the page
    "api",  # your own scenario
    "cli",  # the stickslip command
)


def _unit(path: Path) -> str:
    rel = path.relative_to(PACKAGE)
    return rel.parts[0] if len(rel.parts) > 1 else rel.stem


def test_every_package_has_a_layer_and_imports_only_its_own_or_lower_layers():
    from stickslip.pipeline.code_deps import _direct_dependencies

    rank = {unit: i for i, unit in enumerate(LAYER_ORDER)}
    units = {_unit(p) for p in PACKAGE.rglob("*.py")} - {"__init__"}
    assert units <= set(rank), f"no layer for {sorted(units - set(rank))}: add it to LAYER_ORDER"
    upward = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if path == PACKAGE / "__init__.py":  # loads api and cli by name on first use: above everything
            continue
        source = _unit(path)
        for dep in _direct_dependencies(path.resolve(), SRC.resolve()):
            # the root package's __init__ runs before any submodule, whoever imports it
            if dep == (PACKAGE / "__init__.py").resolve() or not dep.is_relative_to(PACKAGE.resolve()):
                continue
            target = _unit(PACKAGE / dep.relative_to(PACKAGE.resolve()))
            if rank[target] > rank[source]:
                upward.append(f"{path.relative_to(PACKAGE)} ({source}) imports {target}")
    assert not upward, "imports pointing up the layers:\n" + "\n".join(upward)
