# Issue 3: exact reference vs integration methods (work-precision charts, failure map, notebook).
from snakemake.utils import validate

validate(config, "../schemas/methods.schema.yaml")

METHODS_SCENES = list(config["methods_study"]["scenes"])


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


check_methods_config(config["methods_study"])
METHODS_NC = expand("results/methods/{scene}_work_precision.nc", scene=METHODS_SCENES)
METHODS_PNG = expand("results/figures/methods/{scene}_work_precision.png", scene=METHODS_SCENES)

ALL_TARGETS.extend(
    expand("results/methods/{scene}_work_precision.nc", scene=METHODS_SCENES)
    + [
        "results/methods/failure_map.nc",
        "results/figures/methods/failure_map.png",
        "results/notebooks/methods_work_precision.html",
    ]
)


rule methods_work_precision:
    output:
        "results/methods/{scene}_work_precision.nc",
    log:
        "results/logs/methods_work_precision/{scene}.log",
    benchmark:
        "results/benchmarks/methods_work_precision/{scene}.tsv"
    wildcard_constraints:
        scene="|".join(METHODS_SCENES),
    params:
        study=config["methods_study"],  # rerun when the study config changes
    script:
        "../scripts/methods_work_precision.py"


rule methods_failure_map:
    output:
        "results/methods/failure_map.nc",
    log:
        "results/logs/methods_failure_map/all.log",
    benchmark:
        "results/benchmarks/methods_failure_map/all.tsv"
    params:
        study=config["methods_study"],
    script:
        "../scripts/methods_failure_map.py"


rule methods_figures:
    input:
        work_precision=METHODS_NC,
        failure_map="results/methods/failure_map.nc",
    output:
        work_precision=[
            report(
                p,
                caption=REPORT_CAPTION_FILE,
                category="Integration methods",
                labels={"chart": Path(p).stem},
            )
            for p in METHODS_PNG
        ],
        failure_map=report(
            "results/figures/methods/failure_map.png",
            caption=REPORT_CAPTION_FILE,
            category="Integration methods",
            labels={"chart": "failure_map"},
        ),
    log:
        "results/logs/methods_figures/all.log",
    benchmark:
        "results/benchmarks/methods_figures/all.tsv"
    script:
        "../scripts/methods_figures.py"


rule methods_notebook:
    input:
        notebook="notebooks/methods_work_precision.py",
        data=METHODS_NC + ["results/methods/failure_map.nc"],
        figures=METHODS_PNG + ["results/figures/methods/failure_map.png"],
    output:
        report(
            "results/notebooks/methods_work_precision.html",
            caption=REPORT_CAPTION_FILE,
            category="Notebooks",
            labels={"notebook": "methods_work_precision"},
        ),
    log:
        "results/logs/methods_notebook/all.log",
    benchmark:
        "results/benchmarks/methods_notebook/all.tsv"
    params:
        python=sys.executable,
    shell:
        "{params.python} workflow/scripts/render_notebook.py {input.notebook} {output} > {log} 2>&1"
