# Issue 3: exact reference vs integration methods (work-precision charts, failure map, notebook).

METHODS_SCENES = list(config["methods_study"]["scenes"])

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
    priority: PRIORITY["methods_work_precision"]
    conda:
        CONDA_ENV
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
    priority: PRIORITY["methods_failure_map"]
    conda:
        CONDA_ENV
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
    conda:
        CONDA_ENV
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
    conda:
        CONDA_ENV
    script:
        "../scripts/methods_notebook.py"
