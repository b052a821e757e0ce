"""The package's layers import downwards only: no science module can reach the presentation package or the
pipeline's config layer, whatever it imports lazily (the import closure of stickslip.pipeline.code_deps)."""

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
