# Issue 3: exact reference vs integration methods (work-precision charts, failure map, notebook).

METHODS_SCENES = list(config["methods_study"]["scenes"])

METHODS_NC = [paths.methods_work_precision(s) for s in METHODS_SCENES]
METHODS_PNG = [paths.figure("methods", f"{s}_work_precision") for s in METHODS_SCENES]
METHODS_FAILURE_PNG = paths.figure("methods", "failure_map")
METHODS_NOTEBOOK = paths.notebook("methods_work_precision")

ALL_TARGETS.extend(METHODS_NC + [paths.methods_failure_map(), METHODS_FAILURE_PNG, METHODS_NOTEBOOK])


rule methods_work_precision:
    output:
        paths.methods_work_precision("{scene}"),
    log:
        paths.log("methods_work_precision", "{scene}"),
    benchmark:
        paths.benchmark("methods_work_precision", "{scene}")
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
        paths.methods_failure_map(),
    log:
        paths.log("methods_failure_map", "all"),
    benchmark:
        paths.benchmark("methods_failure_map", "all")
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
        failure_map=paths.methods_failure_map(),
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
            METHODS_FAILURE_PNG,
            caption=REPORT_CAPTION_FILE,
            category="Integration methods",
            labels={"chart": "failure_map"},
        ),
    log:
        paths.log("methods_figures", "all"),
    benchmark:
        paths.benchmark("methods_figures", "all")
    conda:
        CONDA_ENV
    script:
        "../scripts/methods_figures.py"


rule methods_notebook:
    input:
        notebook="notebooks/methods_work_precision.py",
        data=METHODS_NC + [paths.methods_failure_map()],
        figures=METHODS_PNG + [METHODS_FAILURE_PNG],
    output:
        report(
            METHODS_NOTEBOOK,
            caption=REPORT_CAPTION_FILE,
            category="Notebooks",
            labels={"notebook": "methods_work_precision"},
        ),
    log:
        paths.log("methods_notebook", "all"),
    benchmark:
        paths.benchmark("methods_notebook", "all")
    conda:
        CONDA_ENV
    script:
        "../scripts/methods_notebook.py"
