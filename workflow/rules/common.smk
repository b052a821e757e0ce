# Shared definitions for every rules file: config validation, target list, helpers.
import json
import shlex
import sys
from pathlib import Path

from snakemake.utils import validate

sys.path.insert(0, str(Path(workflow.basedir) / "src"))  # the package, also when not pip-installed

import re  # noqa: E402
from glob import glob  # noqa: E402

from stickslip.ensemble import EnsembleSpec  # noqa: E402
from stickslip.io.claims import load_claims, required_datasets  # noqa: E402
from stickslip.io.dense_map import dense_map  # noqa: E402

validate(config, "../schemas/config.schema.yaml")

#: Perturbation ensemble of every dataset a claim reads (stickslip.ensemble); a bad value fails here.
ENSEMBLE = config.get("ensemble")
try:
    EnsembleSpec.from_mapping(ENSEMBLE)
except (ValueError, TypeError) as exc:
    raise ValueError(str(exc) if str(exc).startswith("ensemble.") else f"ensemble: {exc}") from None

CLAIM_FILES = sorted(glob(str(Path(workflow.basedir) / "config" / "claims" / "*.yaml")))
#: Every dataset some claim reads: these carry a perturbation ensemble, so each claim has a spread.
CLAIMED_DATASETS = set(required_datasets(load_claims(CLAIM_FILES), config["claims"]["readings"]))

#: The software of every rule, for `--sdm conda` (the default run uses the project's venv: `make figures`).
CONDA_ENV = "../envs/stickslip.yaml"

#: Final outputs; every rules file appends its own.
ALL_TARGETS = []

ONEDOF = config["onedof"]

#: One caption template for every figure of `snakemake --report` (written by rule report_captions). An
#: absolute path under the working directory, since report() resolves captions against the rules folder.
REPORT_CAPTIONS = "results/report/captions.rst"
REPORT_CAPTION_FILE = str(Path(REPORT_CAPTIONS).resolve())


def onedof_subconfig(reading=None, scene=None, method=None, methods=None):
    """The part of the config a 1-DOF job reads, passed as its params: editing a figure list, a notebook or
    another reading then does not re-run it (Snakemake re-runs jobs whose params change)."""
    sub = {k: v for k, v in ONEDOF.items() if k not in ("figures", "sweep_figures")}
    for key, name in (("readings", reading), ("scenes", scene), ("methods", method)):
        if name is not None:
            sub[key] = {name: ONEDOF[key][name]}
    if methods is not None:
        sub["methods"] = {m: ONEDOF["methods"][m] for m in methods}
    return {"onedof": sub}


def onedof_dataset(scene, reading, method):
    return f"results/onedof/{scene}/{reading}/{method}.nc"


def onedof_runs():
    """scene -> sorted (reading, method) pairs that any figure, claim, notebook or the friction table reads:
    one job per scene computes them all (each run takes milliseconds, a job's start-up seconds)."""
    wanted = set(CLAIMED_DATASETS)
    for fig in ONEDOF["figures"]:
        wanted.update(figure_datasets(fig))
    for name in config["notebooks"]:
        wanted.update(notebook_inputs(name))
    table = ONEDOF["friction_table"]
    wanted.add(onedof_dataset(table["scene"], table["reading"], table["method"]))
    runs = {}
    for path in wanted:
        m = re.fullmatch(r"results/onedof/([^/]+)/([^/]+)/([^/]+)\.nc", path)
        if m and m[1] in ONEDOF["scenes"] and m[2] in ONEDOF["readings"] and m[3] in ONEDOF["methods"]:
            runs.setdefault(m[1], set()).add((m[2], m[3]))
    return {scene: sorted(pairs) for scene, pairs in sorted(runs.items())}


def onedof_batch_subconfig(scene, runs):
    """The config one scene's batch job reads (only its readings and methods)."""
    sub = onedof_subconfig(scene=scene)["onedof"]
    sub["readings"] = {r: ONEDOF["readings"][r] for r in sorted({r for r, _ in runs})}
    sub["methods"] = {m: ONEDOF["methods"][m] for m in sorted({m for _, m in runs})}
    return {"onedof": sub}


def figure_datasets(figure):
    fig = ONEDOF["figures"][figure]
    return [onedof_dataset(fig["scene"], r, m) for r in fig["readings"] for m in fig["methods"]]


# -- parse-time checks (a bad value fails before any job starts, naming the key) ----------------------


def check_fe_config(fe_cfg, producible, studies=("convergence", "stability")):
    """Resolve every FE scene and reference at parse time, so a bad value fails before any job starts,
    with the config key named (the schema cannot see NaN, unknown scene names or a missing table)."""
    from stickslip.fe.pipeline import scene_mapping
    from stickslip.fe.scene import SceneParams

    for name in fe_cfg["scenes"]:
        mapping = scene_mapping(fe_cfg, name)
        try:
            SceneParams.from_mapping(
                {k: v for k, v in mapping.items() if k in ("beam", "disc", "contact", "solver")}
            )
        except (ValueError, TypeError, KeyError) as exc:
            raise ValueError(f"fe.scenes.{name}: {exc}") from None
    refs = [(f"fe.sweeps.{n}.base", sw["base"]) for n, sw in fe_cfg["sweeps"].items()]
    refs += [(f"fe.{study}.base", fe_cfg[study]["base"]) for study in studies]
    refs += [(f"fe.cross_scene.{n}", s) for n, pair in fe_cfg["cross_scene"].items() for s in pair[:2]]
    for key, scene in refs:
        if scene not in fe_cfg["scenes"]:
            raise ValueError(f"{key}: {scene!r} is not a scene of fe.scenes ({sorted(fe_cfg['scenes'])})")
    table = fe_cfg["friction_table"]
    if table not in producible and not Path(table).is_file():
        raise ValueError(
            f"fe.friction_table: {table!r} does not exist and no rule writes it (rule friction_table writes {producible})"
        )


def check_methods_config(cfg):
    """Build every scene model and method of the study at parse time, so a bad value fails before any job
    starts with the config key named (the schema cannot see NaN or an unknown solver setting)."""
    from stickslip.model import BeltModel, BeltParams
    from stickslip.model.params import ParameterError
    from stickslip.solvers import make_solver

    fm = cfg["failure_map"]
    runs = [(f"methods_study.scenes.{s}", s, {}) for s in cfg["scenes"]]
    runs += [
        (f"methods_study.failure_map.values[{i}]", fm["scene"], {fm["parameter"]: v})
        for i, v in enumerate(fm["values"])
    ]
    for key, scene, overrides in runs:
        if scene not in cfg["scenes"]:
            raise ValueError(f"{key}: {scene!r} is not a scene of methods_study.scenes")
        spec = cfg["scenes"][scene]
        try:
            BeltModel.build(
                BeltParams.from_mapping({**cfg["base_params"], **spec.get("params", {}), **overrides}),
                spec["variant"],
            )
        except (ParameterError, ValueError, TypeError, KeyError) as exc:
            raise ValueError(f"{key} (with methods_study.base_params): {exc}") from None
    from stickslip.studies.methods import expand_methods

    groups = [("methods", cfg["methods"]), ("failure_map.methods", fm["methods"])]
    groups.append(("paper_method", [cfg["paper_method"]]))
    for key, entries in groups:  # every swept combination of settings, not only the fixed ones
        for solver, settings, label in expand_methods(entries):
            try:
                make_solver(solver, **settings)
            except (ValueError, TypeError, KeyError) as exc:
                raise ValueError(f"methods_study.{key}: {label}: {exc}") from None


# -- notebooks ------------------------------------------------------------------------------------------


def notebook_params(name):
    """What the notebook is told: its figures' and sweep figures' specs (scene, readings, methods), the
    claims readings and the critical-speed readings, so it draws exactly what the DAG built for it."""
    spec = config["notebooks"][name]
    critical = ONEDOF.get("critical_speed") or {}
    return {
        "figures": {fig: ONEDOF["figures"][fig] for fig in spec.get("figures", [])},
        "sweep_figures": {fig: ONEDOF["sweep_figures"][fig] for fig in spec.get("sweep_figures", [])},
        "claims_readings": config["claims"]["readings"],
        "critical_speed_readings": critical.get("readings", []),
    }


def notebook_inputs(name):
    """Every file the notebook reads. An `inputs:` entry containing `{reading}` is expanded over the claims
    readings (the readings whose datasets the claims table already requires), `{critical_reading}` over the
    readings of the critical-speed continuation."""
    spec = config["notebooks"][name]
    expand_over = {
        "reading": config["claims"]["readings"],
        "critical_reading": (ONEDOF.get("critical_speed") or {}).get("readings", []),
    }
    files = []
    for path in spec.get("inputs", []):
        key = next((k for k in expand_over if f"{{{k}}}" in path), None)
        files += [path.format(**{key: r}) for r in expand_over[key]] if key else [path]
    for fig in spec.get("figures", []):
        files += figure_datasets(fig)
        files += [f"results/figures/{fig}/{r}.png" for r in ONEDOF["figures"][fig]["readings"]]
    for fig in spec.get("sweep_figures", []):
        sw = ONEDOF["sweep_figures"][fig]
        files += [sweep_dataset(sw["sweep"], r, d) for r in sw["readings"] for d in (False, True)]
        files += [f"results/figures/{fig}/{r}.png" for r in sw["readings"]]
    return list(dict.fromkeys(files + ["results/claims/deviations.csv"]))


# -- sweeps and maps ----------------------------------------------------------------------------------


def sweep_dataset(sweep, reading, dense=False):
    return f"results/onedof/sweeps/{sweep}{'_dense' if dense else ''}/{reading}.nc"


def dense_map_chunks(wildcards):
    return expand(
        "results/dense_map/chunks/{map}/{chunk}.nc",
        map=wildcards.map,
        chunk=range(dense_map(config, wildcards.map).chunks),
    )
