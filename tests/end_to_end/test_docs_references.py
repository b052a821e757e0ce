"""What README.md and docs/*.md name exists: every `make` target, every `python -m` module, every file or
folder of the repository (tests/cli/test_cli_docs.py runs the `stickslip` commands,
tests/end_to_end/test_extending.py the EXTENDING recipes)."""

import importlib.util
import re

import pytest

from project_run import ROOT

PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
TEXT = {p.name: p.read_text() for p in PAGES}
#: Folders of the repository whose paths the pages cite (results/ and build/ are made by a build, trials/
#: by the reader).
TRACKED = ("src/", "config/", "workflow/", "docs/", "tests/", "benchmarks/", "notebooks/", "requirements/")
ROOTS = "|".join(re.escape(t) for t in TRACKED)
PATH = re.compile(r"(?<![\w./-])((?:" + ROOTS + r")[\w./*{}<>-]*)")


def cited(pattern: re.Pattern) -> list[tuple[str, str]]:
    return sorted({(page, m.group(1)) for page, text in TEXT.items() for m in pattern.finditer(text)})


MAKE = re.compile(r"(?<![\w-])make (?!targets)([a-z][a-z-]*)")
MODULE = re.compile(r"python -m (stickslip[\w.]*)")


def makefile_targets() -> set[str]:
    return set(re.findall(r"^([a-z][a-z-]*):", (ROOT / "Makefile").read_text(), re.M))


@pytest.mark.parametrize(("page", "target"), cited(MAKE))
def test_every_make_target_the_pages_name_is_in_the_makefile(page, target):
    assert target in makefile_targets(), f"{page}: `make {target}` is no target of the Makefile"


@pytest.mark.parametrize(("page", "module"), cited(MODULE))
def test_every_python_module_the_pages_run_exists(page, module):
    assert importlib.util.find_spec(module.rstrip(".")) is not None, f"{page}: no module {module}"


#: Files the EXTENDING recipes write (`yaml file=PATH` blocks): the reader makes them.
WRITTEN = set(re.findall(r"```\w+ (?:file|append)=(\S+)", TEXT["EXTENDING.md"]))


def _exists(path: str) -> bool:
    path = path.rstrip(".,:;)")
    if re.search(r"[<{]", path):  # a template (`config/claims/<file>.yaml`): its folder must exist
        path = re.split(r"[<{]", path)[0].rsplit("/", 1)[0]
    if "*" in path:
        return any(ROOT.glob(path))
    return (ROOT / path).exists()


@pytest.mark.parametrize(
    ("page", "path"), [c for c in cited(PATH) if not c[1].endswith(("/", "."))] or [("", "")]
)
def test_every_repository_path_the_pages_cite_exists(page, path):
    assert not path or path in WRITTEN or _exists(path), f"{page}: {path} does not exist"


def test_the_readmes_time_budgets_are_the_benchmarks_targets():
    """The README's budgets are the ones benchmarks/bench_pipeline.py measures against."""
    import importlib.util as iu

    spec = iu.spec_from_file_location("bench_pipeline", ROOT / "benchmarks" / "bench_pipeline.py")
    bench = iu.module_from_spec(spec)
    spec.loader.exec_module(bench)
    build, tests = (int(bench.TARGETS[k]) for k in ("clean make figures", "clean make test"))
    text = " ".join(TEXT["README.md"].split())
    assert f"a clean build is budgeted at {build} s including the install and the tests at {tests} s" in text
