"""The catalogue (stickslip.catalogue) is the one place a results/ path is made: no other module of the
package, script, rules file or notebook writes one, every claim names a catalogue path, and the paths are the
ones the pipeline has always written (a changed layout would orphan every built result)."""

from __future__ import annotations

import ast
import inspect
import re
import subprocess
import sys

import pytest
import yaml

from stickslip import catalogue as paths
from stickslip.claims.load import ClaimsError, check_claims, load_claims, required_datasets
from stickslip.claims.per_reading import in_reading, repoint
from stickslip.claims.rows import Claim
from stickslip.pipeline.config import drop_removed, load_config

from project_run import ROOT, run_snakemake, small_config_args

#: The catalogue itself, the one module that makes the paths.
THE_CATALOGUE = "src/stickslip/catalogue.py"
LITERAL = "results/"


def is_path_literal(text: str) -> bool:
    """A string that makes a results/ path: starts with it (``"results/fe/"``, an f-string's first part) or
    joins it onto a folder (``"/results/"``). Prose that mentions a file (a usage line, a description) is not
    a path the code opens."""
    return text.startswith(LITERAL) or f"/{LITERAL}" in text


def _docstrings(tree: ast.AST) -> set[int]:
    """ids of the docstring nodes (prose about where files live is not a path the code uses)."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                out.add(id(body[0].value))
    return out


def python_literals(source: str) -> list[tuple[int, str]]:
    """(line, text) of every string constant that makes a results/ path, f-string parts included, docstrings
    not."""
    tree = ast.parse(source)
    skip = _docstrings(tree)
    return [
        (node.lineno, node.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and is_path_literal(node.value)
        and id(node) not in skip
    ]


SMK_LITERAL = re.compile(r"""[rbuf]*["']results/""")


def snakemake_literals(source: str) -> list[tuple[int, str]]:
    """(line, text) of every quoted string in a rules file that starts with ``results/`` (comments aside)."""
    return [
        (i, line.strip())
        for i, line in enumerate(source.splitlines(), 1)
        if not line.lstrip().startswith("#") and SMK_LITERAL.search(line.split(" #")[0])
    ]


def scanned_files() -> list[str]:
    folders = ("src", "workflow", "notebooks", "benchmarks")
    py = [p for folder in folders for p in ROOT.glob(f"{folder}/**/*.py")]
    smk = [*ROOT.glob("workflow/rules/*.smk"), ROOT / "Snakefile"]
    return sorted(str(p.relative_to(ROOT)) for p in py + smk if p.is_file())


def literals_of(rel: str) -> list[tuple[int, str]]:
    text = (ROOT / rel).read_text()
    return python_literals(text) if rel.endswith(".py") else snakemake_literals(text)


def test_the_scanners_find_what_they_look_for():
    assert python_literals('x = f"results/fe/{r}.nc"\n') == [(1, "results/fe/")]
    assert python_literals('x = root + "/results/claims/x.csv"\n') == [(1, "/results/claims/x.csv")]
    assert python_literals('"""results/ in a docstring"""\nx = "usage: check results/x.csv"\n') == []
    assert snakemake_literals('    output:\n        "results/fe/x.nc",\n') == [(2, '"results/fe/x.nc",')]
    assert snakemake_literals("# results/ in a comment\n") == []


def test_no_results_path_is_written_outside_the_catalogue():
    found = {
        rel: hits for rel in scanned_files() if rel != THE_CATALOGUE for hits in [literals_of(rel)] if hits
    }
    listing = "\n".join(f"{rel}:{line}: {text!r}" for rel, hits in found.items() for line, text in hits)
    assert not found, f"results/ paths written outside stickslip.catalogue (use its functions):\n{listing}"


def test_the_catalogue_imports_nothing_of_the_project():
    code = "import sys, stickslip.catalogue as c; print(sorted(m for m in sys.modules if 'stickslip' in m))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "['stickslip', 'stickslip._version', 'stickslip.catalogue']"


# ----------------------------------------------------------------------------------- paths as they were
@pytest.mark.parametrize(
    "made, path",
    [
        (paths.onedof_dataset("fig02", "eq3_text", "exact"), "results/onedof/fig02/eq3_text/exact.nc"),
        (paths.sweep_dataset("fig12", "eq3_text", True), "results/onedof/sweeps/fig12_dense/eq3_text.nc"),
        (paths.friction_table(), "results/onedof/friction_mu_vr.csv"),
        (paths.fe_scene("{fe_reading}", "{scene}"), "results/fe/{fe_reading}/{scene}.nc"),
        (paths.fe_cross_scene("lower_face_drop"), "results/fe/lower_face_drop/cross_scene.nc"),
        (paths.fe_study("setup_fit_0p5mm_s"), "results/fe/setup_fit_0p5mm_s.nc"),
        (paths.fe_continuum_window("section11_x"), "results/fe/continuum_window/section11_x.nc"),
        (paths.fe_deck("peer_free"), "results/fe/inp/peer_free.inp"),
        (paths.figure("fe", "fig21"), "results/figures/fe/fig21.png"),
        (paths.inverse_corner("joint", "affine"), "results/inverse/corner/joint_affine.png"),
        (paths.dense_map_chunk("{map}", "{chunk}"), "results/dense_map/chunks/{map}/{chunk}.nc"),
        (paths.claims_table("md"), "results/claims/deviations.md"),
        (paths.log("claims_check"), "results/logs/claims_check.log"),
        (paths.log("dense_map_chunk", "{map}/{chunk}"), "results/logs/dense_map_chunk/{map}/{chunk}.log"),
        (paths.benchmark("fe_reading", "{fe_reading}"), "results/benchmarks/fe_reading/{fe_reading}.tsv"),
        (paths.page(), "results/index.html"),
    ],
)  # fmt: skip
def test_paths_are_the_ones_the_pipeline_has_always_written(made, path):
    assert made == path


def project_config(small: bool = False) -> dict:
    files = sorted((ROOT / "config").glob("*.yaml"))
    files += sorted((ROOT / "config" / "test").glob("*.yaml")) if small else []
    return drop_removed(load_config(files))


@pytest.fixture(scope="module", params=[False, True], ids=["full", "small"])
def config_and_catalogue(request):
    config = project_config(small=request.param)
    return config, paths.catalogue(config)


def test_every_entry_is_typed_and_keyed_by_its_path(config_and_catalogue):
    _, cat = config_and_catalogue
    for path, entry in cat.items():
        assert entry.path == path and paths.is_result(path) and entry.kind and entry.rule
        assert all(isinstance(k, str) and isinstance(v, str) for k, v in entry.names)


def test_every_claimed_dataset_is_a_catalogue_entry(config_and_catalogue):
    config, cat = config_and_catalogue
    claims = load_claims(sorted((ROOT / "config" / "claims").glob("*.yaml")))
    missing = [p for p in required_datasets(claims, config["claims"]["readings"]) if p not in cat]
    assert not missing


def test_a_claim_outside_the_catalogue_is_refused_naming_its_row_and_key(tmp_path):
    """A real beam-on-disc row pointed at a scene the config does not have."""
    config = project_config()
    rows = yaml.safe_load((ROOT / "config" / "claims" / "sections_09_12.yaml").read_text())
    row = next(r for r in rows if "dataset" in r and "twin" not in r)
    row = {**row, "id": "s9_off_catalogue", "dataset": "results/fe/lower_face_drop/section9_no_such_scene.nc"}
    (tmp_path / "rows.yaml").write_text(yaml.safe_dump([row]))
    claims = load_claims([tmp_path / "rows.yaml"])
    refused = r"rows\.yaml: claim s9_off_catalogue: dataset: no rule writes .*no_such_scene.*catalogue path"
    with pytest.raises(ClaimsError, match=refused):
        check_claims(claims, config["claims"]["readings"], catalogue=paths.catalogue(config))


def test_paper_figures_of_the_config_reach_the_entries():
    config = project_config()
    cat = paths.catalogue(config)
    entry = cat[paths.fe_scene("lower_face_drop", "section9_kinematic_15p2rpm")]
    assert entry.kind == "fe_scene" and entry.rule == "fe_reading"
    assert entry.figures == (21, 22, 23, 24, 25)
    assert cat[paths.figure("fe", "fig31")].figures == (31,)


# --------------------------------------------------------------------- a claim read in another FE reading
SCENES, READINGS = ["section9_a", "section9_b"], ["default", "upper"]
FE_ENTRIES = {e.path: e for e in paths.fe_scene_entries(SCENES, READINGS)}


def test_the_same_run_is_found_in_another_reading_by_its_entry():
    assert in_reading(paths.fe_scene("default", "section9_b"), "upper", FE_ENTRIES) == paths.fe_scene(
        "upper", "section9_b"
    )
    assert in_reading(paths.fe_cross_scene("default"), "upper", FE_ENTRIES) == paths.fe_cross_scene("upper")
    shared = paths.fe_study("angle_sweep")  # no reading: every reading reads it as it is
    assert in_reading(shared, "upper", FE_ENTRIES) == shared


def test_a_reading_the_catalogue_does_not_have_is_an_error_naming_the_path():
    with pytest.raises(KeyError, match="section9_a"):
        in_reading(paths.fe_scene("default", "section9_a"), "nowhere", FE_ENTRIES)


def test_repoint_moves_every_operand_and_leaves_the_row_alone():
    claim = Claim.model_validate(
        {
            "id": "c",
            "section": "9",
            "figure": "Fig. 21",
            "figures": [21],
            "quote": "q",
            "kind": "compare",
            "expected": "reproduced",
            "evidence": "evidence",
            "model": "beam",
            "lhs": {"dataset": paths.fe_scene("default", "section9_a"), "variable": "x"},
            "relation": ">",
            "rhs": {"dataset": paths.fe_study("angle_sweep"), "variable": "y"},
        }
    )
    moved = repoint(claim, "upper", FE_ENTRIES)
    assert moved.lhs.dataset == paths.fe_scene("upper", "section9_a")
    assert moved.rhs.dataset == paths.fe_study("angle_sweep")
    assert claim.lhs.dataset == paths.fe_scene("default", "section9_a")  # a copy
    assert moved.model_copy(update={"lhs": claim.lhs}) == claim  # nothing but the dataset moved


def test_a_1dof_figures_title_names_the_paper_figures_its_config_entry_maps():
    """The map (``paper_figures``) decides; the title a reader sees must not say otherwise."""
    from stickslip.presentation.report import paper_figures as named_in

    onedof = project_config()["onedof"]
    for section in ("figures", "sweep_figures"):
        for name, fig in onedof[section].items():
            assert named_in(fig["title"]) == set(fig["paper_figures"]), f"onedof.{section}.{name}"


def test_1dof_runs_show_the_paper_figures_drawn_from_them():
    cat = paths.catalogue(project_config())
    assert cat[paths.onedof_dataset("fig07", "plateau_text", "exact")].figures == (7, 8, 9)  # Figs. 7-9
    assert cat[paths.sweep_dataset("fig12", "plateau_text", True)].figures == (12, 13)
    assert cat[paths.eq6_curve()].figures == (4,)
    assert cat[paths.sweep_dataset("belt_speed", "plateau_text")].figures == ()  # drawn by no paper figure


#: Outputs of the DAG that are no catalogue entry: a dense map's chunks (temporary; how many is decided by
#: studies.specs at parse time).
NOT_CATALOGUED = (re.compile(r"results/dense_map/chunks/"),)
#: Entries a configuration builds only where something reads them: the 1-DOF runs and sweeps a figure,
#: claim or notebook reads, and the claims check where ``claims.check`` asks for it (the small one does not).
BUILT_WHERE_READ = ("onedof_dataset", "sweep_dataset", "claims_check")


def dry_run_jobs(text: str) -> list[tuple[str, list[str]]]:
    """(rule, outputs) of every job a ``snakemake -n`` listing shows."""
    jobs, rule = [], None
    for line in text.splitlines():
        started = re.match(r"^(?:local)?rule (\S+):", line)
        if started:
            rule = started.group(1)
        elif rule and (out := re.match(r"^\s+output: (.*)$", line)):
            jobs.append((rule, [o.strip() for o in out.group(1).split(",")]))
    return jobs


def test_the_scanner_reads_a_dry_run_listing():
    text = (
        "rule a:\n    input: x\n    output: results/p.nc, results/q.nc\nlocalrule b:\n    output: results/r\n"
    )
    assert dry_run_jobs(text) == [("a", ["results/p.nc", "results/q.nc"]), ("b", ["results/r"])]


@pytest.mark.pipeline
def test_the_dag_writes_the_catalogue_by_the_rules_it_names_and_nothing_else():
    """The rules take their outputs from the catalogue's declarations (``outputs``): a forced dry run of the
    small configuration shows that they do, every output an entry written by the rule the entry names, every
    entry written (but where the configuration builds a family only where it is read)."""
    text = run_snakemake(ROOT, "-n", "-F", "--nolock", *small_config_args(ROOT), timeout=300).stdout
    cat = paths.catalogue(project_config(small=True))
    made = {
        o: rule
        for rule, outs in dry_run_jobs(text)
        for o in outs
        if not any(p.search(o) for p in NOT_CATALOGUED)
    }
    assert len(made) > 100
    assert [o for o in made if o not in cat] == []
    assert [(o, rule, cat[o].rule) for o, rule in made.items() if cat[o].rule != rule] == []
    assert [p for p, e in cat.items() if p not in made and e.kind not in BUILT_WHERE_READ] == []


# -------------------------------------------------------------------------------- templates and outputs


def test_a_path_template_is_called_as_the_function_it_stands_for():
    assert str(inspect.signature(paths.fe_scene)) == "(reading, scene)"
    assert paths.fe_scene(scene="s", reading="r") == paths.fe_scene("r", "s") == "results/fe/r/s.nc"
    assert paths.friction_table() == paths.friction_table("csv") and paths.validation_round_trip().endswith(
        ".nc"
    )
    with pytest.raises(TypeError, match="scene"):
        paths.fe_scene("r")
    templates = {name: t for name, t in vars(paths).items() if isinstance(t, paths.PathTemplate)}
    assert len(templates) > 30 and all(t.__name__ == name for name, t in templates.items())


def test_a_rules_outputs_are_named_and_ordered_as_its_script_reads_them():
    config = project_config()
    scenes, readings = list(config["fe"]["scenes"]), config["onedof"]["figures"]["fig02"]["readings"]
    assert paths.outputs(config, "fe_reading", reading="{fe_reading}") == {
        "scenes": [paths.fe_scene("{fe_reading}", s) for s in scenes],
        "cross": paths.fe_cross_scene("{fe_reading}"),
    }
    assert paths.outputs(config, "fe_setup_fit", name="{fe_fit}") == {"fit": paths.fe_study("{fe_fit}")}
    assert paths.outputs(config, "friction_table") == {
        "csv": paths.friction_table("csv"),
        "nc": paths.friction_table("nc"),
    }
    assert paths.outputs(config, "onedof_figure_fig02") == {
        "figures": [paths.figure("fig02", r) for r in readings]
    }
    assert paths.outputs(config, "no_such_rule") == {}


def test_the_fe_paper_figures_are_the_configs_registry():
    """Which FE paper-figure images exist and what each shows: the config's ``fe.paper_figures`` alone."""
    config = project_config()
    config["fe"]["paper_figures"] = {22: ["section9_kinematic_0p5mm_s"]}
    cat = paths.catalogue(config)
    paper = [e for e in cat.values() if e.rule == "fe_figures" and e.name("name").startswith("fig")]
    assert [(e.path, e.figures) for e in paper] == [(paths.figure("fe", "fig22"), (22,))]
    assert cat[paths.fe_scene("lower_face_drop", "section9_kinematic_0p5mm_s")].figures == (22,)
    assert cat[paths.fe_scene("lower_face_drop", "section9_kinematic_15p2rpm")].figures == ()
