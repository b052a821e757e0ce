# Issue 3: exact reference vs integration methods (work-precision charts, failure map, notebook).

METHODS_SCENES = list(CFG.methods_study.scenes)
METHODS_NC = products_of("methods_work_precision")
METHODS_PNG = products_of("methods_figures")

ALL_TARGETS.extend(
    METHODS_NC
    + products_of("methods_failure_map", "methods_notebook")
    + [paths.figure("methods", "failure_map")]
)


rule methods_work_precision:
    output:
        **outputs("methods_work_precision", scene="{scene}"),
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
        study=as_written(CFG.methods_study),  # rerun when the study config changes
    script:
        "../scripts/methods_work_precision.py"


rule methods_failure_map:
    output:
        **outputs("methods_failure_map"),
    log:
        paths.log("methods_failure_map", "all"),
    benchmark:
        paths.benchmark("methods_failure_map", "all")
    priority: PRIORITY["methods_failure_map"]
    conda:
        CONDA_ENV
    params:
        study=as_written(CFG.methods_study),
    script:
        "../scripts/methods_failure_map.py"


rule methods_figures:
    input:
        work_precision=METHODS_NC,
        failure_map=paths.methods_failure_map(),
    output:
        **outputs(
            "methods_figures",
            flags={
                name: report_of("Integration methods", "chart") for name in ("work_precision", "failure_map")
            },
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
        data=METHODS_NC + products_of("methods_failure_map"),
        figures=METHODS_PNG,
    output:
        **outputs("methods_notebook", flags={"notebook": report_of("Notebooks", "notebook")}),
    log:
        paths.log("methods_notebook", "all"),
    benchmark:
        paths.benchmark("methods_notebook", "all")
    conda:
        CONDA_ENV
    script:
        "../scripts/methods_notebook.py"
