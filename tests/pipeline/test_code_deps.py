"""Which package files a job runs: the import scan against Python's own parser, and the hash's behaviour."""

import ast
from pathlib import Path

import pytest

from stickslip.pipeline.code_deps import code_hash, dependency_files, imported_names, module_file

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "src"


def parsed_names(source, module, is_package):
    """The same question answered by the parser: every import statement at any depth."""
    names = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            names.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                anchor = module.split(".")
                anchor = anchor if is_package else anchor[:-1]
                anchor = anchor[: len(anchor) - (node.level - 1)]
                base = ".".join(anchor + ([node.module] if node.module else []))
            else:
                base = node.module
            names.add(base)
            names.update(f"{base}.{a.name}" for a in node.names if a.name != "*")
    return {n for n in names if n == "stickslip" or n.startswith("stickslip.")}


FILES = sorted((SRC / "stickslip").rglob("*.py")) + sorted((ROOT / "workflow" / "scripts").glob("*.py"))


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(ROOT)))
def test_the_import_scan_finds_every_import_the_parser_finds(path):
    inside = path.is_relative_to(SRC)
    parts = list(path.relative_to(SRC).with_suffix("").parts) if inside else []
    is_package = bool(parts) and parts[-1] == "__init__"
    module = ".".join(parts[:-1] if is_package else parts) if inside else None
    source = path.read_text()
    expected = parsed_names(source, module, is_package) if inside else parsed_names(source, "x", False)
    assert expected <= imported_names(source, module, is_package)


def test_relative_imports_resolve_against_the_module_and_its_package():
    source = "from ..model import params\nfrom . import base\nfrom .linear import (\n    a,\n    b as c,\n)\n"
    names = imported_names(source, "stickslip.solvers.exact", is_package=False)
    assert {"stickslip.model.params", "stickslip.solvers.base", "stickslip.solvers.linear.a"} <= names
    assert "stickslip.solvers.linear.b" in names and "stickslip.solvers.linear.c" not in names


def test_a_lazy_import_inside_a_function_counts():
    source = "def f():\n    from stickslip.fe import kernel\n    return kernel\n"
    assert "stickslip.fe.kernel" in imported_names(source)


def test_a_name_from_a_registry_package_depends_on_every_module_it_may_load(tmp_path):
    by_name, by_module = tmp_path / "by_name.py", tmp_path / "by_module.py"
    by_name.write_text("from stickslip.solvers import make_solver\n")
    by_module.write_text("from stickslip.solvers.base import Trajectory\n")
    registry = dependency_files([by_name], SRC)
    assert module_file(SRC, "stickslip.solvers.exact") in registry
    assert module_file(SRC, "stickslip.solvers.moreau") in registry
    one_module = dependency_files([by_module], SRC)
    assert module_file(SRC, "stickslip.solvers") in one_module  # its __init__ runs
    assert module_file(SRC, "stickslip.solvers.exact") not in one_module


def test_a_module_depends_on_its_parent_packages_and_not_on_unrelated_ones():
    files = dependency_files([module_file(SRC, "stickslip.model.params")], SRC)
    assert module_file(SRC, "stickslip") in files and module_file(SRC, "stickslip.model") in files
    assert module_file(SRC, "stickslip.fe.kernel") not in files


def _copy_package(tmp_path):
    import shutil

    shutil.copytree(
        SRC / "stickslip", tmp_path / "src" / "stickslip", ignore=shutil.ignore_patterns("__pycache__")
    )
    return tmp_path / "src"


def test_the_hash_moves_with_a_dependency_ignores_comment_lines_and_returns_on_revert(tmp_path):
    src = _copy_package(tmp_path)
    script = tmp_path / "job.py"
    script.write_text("from stickslip.solvers import make_solver\n")
    exact = src / "stickslip" / "solvers" / "exact.py"
    original = exact.read_text()
    before = code_hash([script], src)

    from stickslip.pipeline import code_deps

    def rehash():
        code_deps._source.cache_clear()
        code_deps._file_digest.cache_clear()
        return code_hash([script], src)

    exact.write_text(original + "\n# a comment line\n\n")
    assert rehash() == before
    exact.write_text(original.replace("return", "return  ", 1))
    assert rehash() != before
    exact.write_text(original)
    assert rehash() == before


def test_the_hash_does_not_depend_on_where_the_project_lives(tmp_path):
    script = "from stickslip.model import params\n"
    hashes = []
    for name in ("a", "b"):
        src = _copy_package(tmp_path / name)
        (tmp_path / name / "job.py").write_text(script)
        hashes.append(code_hash([tmp_path / name / "job.py"], src))
    assert hashes[0] == hashes[1]


def test_a_comment_inside_an_import_list_may_hold_a_parenthesis():
    source = "from .schema.base import (  # noqa: F401  (re-exported)\n    Finite,\n    Positive,\n)\n"
    names = imported_names(source, "stickslip.schema", is_package=False)
    assert {"stickslip.schema.base.Finite", "stickslip.schema.base.Positive"} <= names
