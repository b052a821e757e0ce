"""The config is read as mappings in fewer and fewer places: a ledger of every remaining dict read.

The typed ``PipelineConfig`` (``validate_config`` returns it) is what consumers should take; most still
re-read the validated mapping by key (issue 39). This test walks every module of ``src/stickslip`` outside
``pipeline/`` and every workflow script (Python's AST) and every rules file (text: a ``.smk`` file is not
Python) for a read of the config by key: ``config["x"]``, ``cfg.get("x")``, ``snakemake.config["x"]``, on a
name that holds the config or a section of it (``config``, ``cfg``, ``*_cfg``, ``*_config``). Each file's
count must equal its entry in ``LEDGER``: a new read fails the test, and a removed one must lower the entry,
so the reads only ever go down. A section bound to another name (``fe = config["fe"]``) counts at that one
read, not at each read of ``fe``: the ledger is a floor of the debt, not all of it.
"""

import ast
import re
from functools import cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "src" / "stickslip"


def _is_config_name(node) -> bool:
    if isinstance(node, ast.Attribute):  # snakemake.config
        return node.attr == "config"
    if not isinstance(node, ast.Name):
        return False
    name = node.id
    return name in ("config", "cfg") or name.endswith(("_cfg", "_config"))


def python_reads(source: str) -> int:
    """Reads by a constant string key of a config mapping, or ``.get`` with one, in Python source."""
    count = 0
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant):
            if isinstance(node.slice.value, str) and not isinstance(node.value, ast.Subscript):
                count += _is_config_name(node.value)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "get":
            receiver = node.func.value  # a get on a subscript of a config counts at its subscript
            count += _is_config_name(receiver) and not isinstance(receiver, ast.Subscript)
    return count


def rules_reads(source: str) -> int:
    """The same reads in a rules file, by pattern (the rule syntax is not Python)."""
    return len(re.findall(r"\b(?:config|cfg|\w+_cfg|\w+_config)(?:\[['\"]|\.get\()", source))


@cache
def current_reads() -> dict[str, int]:
    files = [p for p in PACKAGE.rglob("*.py") if "pipeline" not in p.relative_to(PACKAGE).parts]
    files += sorted((ROOT / "workflow" / "scripts").glob("*.py"))
    counts = {str(p.relative_to(ROOT)): python_reads(p.read_text()) for p in files}
    rules = [ROOT / "Snakefile", *sorted((ROOT / "workflow" / "rules").glob("*.smk"))]
    counts |= {str(p.relative_to(ROOT)): rules_reads(p.read_text()) for p in rules}
    return {path: n for path, n in counts.items() if n}


#: file -> config reads by key it still makes (the debt; lower an entry when you remove reads)
LEDGER: dict[str, int] = {
    "src/stickslip/api.py": 3,
    "workflow/rules/common.smk": 1,
    "workflow/rules/inverse.smk": 2,
    "workflow/rules/methods.smk": 3,
    "workflow/rules/validation.smk": 3,
}


def test_the_read_counter_sees_each_form_of_a_config_read():
    source = (
        "a = config['onedof']['scenes']\n"  # one read (a chain counts once, at its root)
        "b = fe_cfg.get('scenes')\n"
        "c = snakemake.config['fe']\n"
        "d = cfg['x'].get('y')\n"  # a get on a subscript of a config: counted by its subscript
        "e = other['x']\n"  # not a config name
        "f = config.fe.scenes\n"  # typed access: not a read by key
    )
    assert python_reads(source) == 4
    assert rules_reads("x = config['a']\ny = fe_cfg.get('b')\nz = typed.fe\n") == 2


@pytest.mark.parametrize("path", sorted(set(current_reads()) | set(LEDGER)))
def test_config_reads_by_key_only_go_down(path):
    now = current_reads().get(path, 0)
    allowed = LEDGER.get(path, 0)
    assert now <= allowed, f"{path}: {now} reads of the config by key, the ledger allows {allowed}"
    assert now == allowed, f"{path}: down to {now} reads of the config by key: lower its LEDGER entry"
