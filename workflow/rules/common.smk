# Shared definitions for every rules file: config validation, target list, helpers.
import json
import shlex
import sys
from pathlib import Path

from snakemake.utils import validate

from stickslip.io.dense_map import dense_map

sys.path.insert(0, str(Path(workflow.basedir) / "src"))  # the package, also when not pip-installed

validate(config, "../schemas/config.schema.yaml")

#: The software of every rule, for `--sdm conda` (the default run uses the project's venv: `make figures`).
CONDA_ENV = "../envs/stickslip.yaml"

#: Final outputs; every rules file appends its own.
ALL_TARGETS = []

ONEDOF = config["onedof"]

#: One caption template for every figure of `snakemake --report` (written by rule report_captions). An
#: absolute path under the working directory, since report() resolves captions against the rules folder.
REPORT_CAPTIONS = "results/report/captions.rst"
REPORT_CAPTION_FILE = str(Path(REPORT_CAPTIONS).resolve())


def onedof_dataset(scene, reading, method):
    return f"results/onedof/{scene}/{reading}/{method}.nc"


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
    for i, entry in enumerate(cfg["methods"] + fm["methods"] + [cfg["paper_method"]]):
        try:
            make_solver(entry["solver"], **entry.get("settings", {}))
        except (ValueError, TypeError, KeyError) as exc:
            raise ValueError(f"methods_study.methods: solver {entry.get('solver')!r}: {exc}") from None


# -- notebooks ------------------------------------------------------------------------------------------


def notebook_params(name):
    """What the notebook is told: its figures' specs (scene, readings, methods) and the claims readings."""
    spec = config["notebooks"][name]
    return {
        "figures": {fig: ONEDOF["figures"][fig] for fig in spec.get("figures", [])},
        "claims_readings": config["claims"]["readings"],
    }


def notebook_inputs(name):
    spec = config["notebooks"][name]
    files = list(spec.get("inputs", []))
    for fig in spec.get("figures", []):
        files += figure_datasets(fig)
        files += [f"results/figures/{fig}/{r}.png" for r in ONEDOF["figures"][fig]["readings"]]
    return files + ["results/claims/deviations.csv"]


# -- sweeps and maps ----------------------------------------------------------------------------------


def sweep_dataset(sweep, reading, dense=False):
    return f"results/onedof/sweeps/{sweep}{'_dense' if dense else ''}/{reading}.nc"


def dense_map_chunks(wildcards):
    return expand(
        "results/dense_map/chunks/{map}/{chunk}.nc",
        map=wildcards.map,
        chunk=range(dense_map(config, wildcards.map).chunks),
    )
