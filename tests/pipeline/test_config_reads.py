"""The config is read by key nowhere after validation: consumers take the typed config (issue 39).

``validate_config`` returns the typed ``PipelineConfig``; the rules read it (``CFG`` in common.smk) and hand
each job the values it reads as params, which the job types once (``stickslip.schema``). This test walks
every module of ``src/stickslip`` outside ``pipeline/`` and every workflow script (Python's AST) and every
rules file (text: a ``.smk`` file is not Python) for a read of the config by key: ``config["x"]``,
``cfg.get("x")``, ``snakemake.config["x"]``, on a name that holds the config or a section of it
(``config``, ``cfg``, ``*_cfg``, ``*_config``). Each file's count must equal its entry in ``LEDGER``: a new
read fails the test. The only entries left build the config before it is validated (the API adds your
scene to the project's files, as a config file would), and say so.
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


#: file -> reads by key of a config not yet validated (the config being built; none after validation)
LEDGER: dict[str, int] = {
    # load_project_config makes inverse.claims_glob a project path; simulate_fe names your scene among
    # fe.scenes before your scene and the project's files are validated together
    "src/stickslip/api.py": 3,
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
