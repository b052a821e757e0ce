"""Which of the package's source files a job runs, and one hash of them, so a job re-runs when its code does.

Snakemake tracks a rule's own script and shell command, not the modules they import. ``code_hash`` gives
each rule one more parameter: a hash of every ``stickslip`` module its entry points (script, ``python -m``
module, notebook) can import. Snakemake re-runs a job whose parameters changed, so an edit under ``src/``
re-runs exactly the rules that import the edited module (and, through their new outputs, their consumers);
reverting the edit restores the hash and schedules nothing.

How the dependency set is found (static, at parse time, no import executed):

* every ``import`` / ``from ... import`` statement anywhere in a file counts, inside functions too (the
  package imports heavy modules lazily, on first use);
* importing ``a.b.c`` runs ``a/__init__.py`` and ``a/b/__init__.py`` too, so those count;
* ``from pkg import name`` counts ``pkg.name`` when that is a module;
* a package whose ``__init__`` calls ``import_module`` (a registry loaded by name: the solvers) may load any
  of its modules when one of its names is used, so taking a name from it (``from stickslip.solvers import
  make_solver``) depends on every module of that package; importing one of its modules does not.

What it leaves out, deliberately: third-party packages (the lock pins them; every dataset records their
versions), data files the code reads (those are rule inputs), and blank or whole-line comment lines (an
edit of those re-runs nothing; any other edit, a docstring or a trailing comment included, re-runs).
"""

from __future__ import annotations

import hashlib
import re
from functools import cache
from pathlib import Path

PACKAGE = "stickslip"


#: An import statement: ``import a.b, c`` or ``from .a import (b, c)`` (parenthesised lists may span lines).
_IMPORT = re.compile(
    r"^[ \t]*(?:import[ \t]+(?P<modules>[\w., \t]+)|from[ \t]+(?P<base>\.*[\w.]*)[ \t]+import[ \t]+"
    r"(?P<names>\((?:[^)#]|#[^\n]*)*\)|[^\n#]+))",  # a comment inside the parentheses may hold a ")"
    re.MULTILINE,
)


@cache
def _source(path: Path) -> str:
    return path.read_text()


@cache
def module_file(src: Path, module: str) -> Path | None:
    """The file of a dotted module name under ``src`` (a package's ``__init__.py``), or None."""
    base = src.joinpath(*module.split("."))
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate.resolve()
    return None


def _module_name(src: Path, path: Path) -> tuple[str, bool]:
    """(dotted name, is a package) of a file under ``src``."""
    parts = list(path.relative_to(src).with_suffix("").parts)
    is_package = parts[-1] == "__init__"
    if is_package:
        parts = parts[:-1]
    return ".".join(parts), is_package


def imported_names(source: str, module: str | None = None, is_package: bool = False) -> set[str]:
    """Dotted names every import statement of ``source`` may load (relative imports resolved against
    ``module``), including ``pkg.name`` for ``from pkg import name`` since ``name`` may be a module.

    Statements are found by a pattern, not by parsing (a parse of every module at each Snakemake start cost
    0.5 s): an import-like line inside a string adds a dependency, never removes one."""
    names: set[str] = set()
    for m in _IMPORT.finditer(source):
        if m["modules"]:
            names.update(part.split(" as ")[0].strip() for part in m["modules"].split(","))
            continue
        dots = len(m["base"]) - len(m["base"].lstrip("."))
        if dots:
            if module is None:
                continue  # a relative import outside the package: not ours
            anchor = module.split(".")
            anchor = anchor if is_package else anchor[:-1]
            anchor = anchor[: len(anchor) - (dots - 1)]
            rest = m["base"][dots:]
            base = ".".join(anchor + ([rest] if rest else []))
        else:
            base = m["base"]
        names.add(base)
        listed = re.sub(r"#[^\n]*", "", m["names"]).strip("() \t\n")
        for part in listed.split(","):
            name = part.split(" as ")[0].strip()
            if name and name != "*":
                names.add(f"{base}.{name}")
    return {n for n in names if n == PACKAGE or n.startswith(PACKAGE + ".")}


def _with_parents(module: str) -> list[str]:
    parts = module.split(".")
    return [".".join(parts[: i + 1]) for i in range(len(parts))]


@cache
def _lazy_package(src: Path, package: str) -> bool:
    """A package whose ``__init__`` loads modules by name (``import_module``: a registry)."""
    init = module_file(src, package)
    return init is not None and init.name == "__init__.py" and "import_module(" in _source(init)


def _by_name(src: Path, package: str) -> set[str]:
    """Every module of a lazy package: any of them may be loaded when one of its names is used."""
    init = module_file(src, package)
    return {_module_name(src, p)[0] for p in init.parent.glob("*.py")}


@cache
def _direct_dependencies(path: Path, src: Path) -> frozenset[Path]:
    """Package files one file imports directly (its parent packages' ``__init__`` included).

    A name taken from a lazy package that is not one of its modules (``from stickslip.solvers import
    make_solver``), or the plain import of such a package, may load any of its modules; importing one of
    its modules (``from stickslip.solvers.base import Trajectory``) runs its ``__init__``, nothing more."""
    inside = path.is_relative_to(src)
    module, is_package = _module_name(src, path) if inside else (None, False)
    source = _source(path)
    names = imported_names(source, module, is_package)
    if inside:
        names.update(_with_parents(module))
    for name in list(names):
        parent = name.rpartition(".")[0]
        if parent and _lazy_package(src, parent) and module_file(src, name) is None:
            names.update(_by_name(src, parent))
        if _lazy_package(src, name) and re.search(rf"^[ \t]*import[ \t]+{re.escape(name)}\b", source, re.M):
            names.update(_by_name(src, name))
    found = {module_file(src, dotted) for name in names for dotted in _with_parents(name)}
    return frozenset(p for p in found if p is not None and p != path)


def dependency_files(entry_points: list[Path], src: Path) -> set[Path]:
    """Every package file reachable by imports from ``entry_points`` (scripts or package modules)."""
    src = src.resolve()
    seen: set[Path] = set()
    todo = [Path(p).resolve() for p in entry_points]
    while todo:
        path = todo.pop()
        if path not in seen:
            seen.add(path)
            todo.extend(_direct_dependencies(path, src) - seen)
    return {p for p in seen if p.is_relative_to(src)}


@cache
def _file_digest(path: Path) -> str:
    """Hash of a file's lines less blank and whole-line comment lines (such an edit re-runs nothing)."""
    kept = [ln for ln in _source(path).splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    return hashlib.sha256("\n".join(kept).encode()).hexdigest()


def code_hash(entry_points: list[Path], src: Path) -> str:
    """One short hash of every package file the entry points can import (paths relative to ``src``, so a
    moved project keeps its hashes); the entry points themselves are tracked by Snakemake already."""
    src = src.resolve()
    digest = hashlib.sha256()
    for path in sorted(dependency_files(entry_points, src)):
        digest.update(f"{path.relative_to(src)}:{_file_digest(path)}\n".encode())
    return digest.hexdigest()[:16]
