# Beam on rotating rigid disc (paper Sections 8-12, issue 5). Scene names come from config["fe"].

FE_SCENES = list(config["fe"]["scenes"])
FE_SWEEPS = list(config["fe"]["sweeps"])
FE_FRICTION = config["fe"]["friction_table"]
FE_STUDIES = ["convergence", "stability"]


rule fe_scene:
    input:
        friction=FE_FRICTION,
    output:
        "results/fe/{scene}.nc",
    log:
        "results/logs/fe_scene/{scene}.log",
    benchmark:
        "results/benchmarks/fe_scene/{scene}.tsv"
    wildcard_constraints:
        scene="|".join(FE_SCENES),
    conda:
        CONDA_ENV
    params:
        ensemble=ENSEMBLE,
    script:
        "../scripts/fe_scene.py"


rule fe_sweep:
    input:
        friction=FE_FRICTION,
    output:
        "results/fe/{sweep}.nc",
    log:
        "results/logs/fe_sweep/{sweep}.log",
    benchmark:
        "results/benchmarks/fe_sweep/{sweep}.tsv"
    wildcard_constraints:
        sweep="|".join(FE_SWEEPS),
    conda:
        CONDA_ENV
    script:
        "../scripts/fe_sweep.py"


rule fe_study:
    input:
        friction=FE_FRICTION,
    output:
        "results/fe/{study}.nc",
    log:
        "results/logs/fe_study/{study}.log",
    benchmark:
        "results/benchmarks/fe_study/{study}.tsv"
    wildcard_constraints:
        study="|".join(FE_STUDIES),
    conda:
        CONDA_ENV
    params:
        kind=lambda wc: wc.study,
    script:
        "../scripts/fe_study.py"


rule fe_cross_scene:
    input:
        sorted({f"results/fe/{s}.nc" for pair in config["fe"]["cross_scene"].values() for s in pair[:2]}),
    output:
        "results/fe/cross_scene.nc",
    log:
        "results/logs/fe_cross_scene/cross_scene.log",
    benchmark:
        "results/benchmarks/fe_cross_scene/cross_scene.tsv"
    conda:
        CONDA_ENV
    script:
        "../scripts/fe_cross.py"


rule fe_figure:
    input:
        "results/fe/{scene}.nc",
    output:
        report(
            "results/figures/fe/{scene}.png",
            caption=REPORT_CAPTION_FILE,
            category="Beam on rotating disc (Sections 9-12)",
            labels={"scene": "{scene}"},
        ),
    log:
        "results/logs/fe_figure/{scene}.log",
    benchmark:
        "results/benchmarks/fe_figure/{scene}.tsv"
    wildcard_constraints:
        scene="|".join(FE_SCENES),
    conda:
        CONDA_ENV
    script:
        "../scripts/fe_figure.py"


FE_DATASETS = (
    [f"results/fe/{s}.nc" for s in FE_SCENES]
    + [f"results/fe/{s}.nc" for s in FE_SWEEPS]
    + [f"results/fe/{s}.nc" for s in FE_STUDIES]
    + ["results/fe/cross_scene.nc"]
)


rule fe_notebook:
    input:
        notebook="notebooks/section_09_12_beam_on_disc.py",
        data=FE_DATASETS,
        figures=[f"results/figures/fe/{s}.png" for s in FE_SCENES],
    output:
        report(
            "results/notebooks/section_09_12_beam_on_disc.html",
            caption=REPORT_CAPTION_FILE,
            category="Notebooks",
            labels={"notebook": "section_09_12_beam_on_disc"},
        ),
    log:
        "results/logs/fe_notebook/section_09_12_beam_on_disc.log",
    benchmark:
        "results/benchmarks/fe_notebook/section_09_12_beam_on_disc.tsv"
    conda:
        CONDA_ENV
    params:
        python=sys.executable,
    shell:
        "{params.python} workflow/scripts/render_notebook.py {input.notebook} {output} > {log} 2>&1"


ALL_TARGETS.extend(FE_DATASETS)
ALL_TARGETS.extend(f"results/figures/fe/{s}.png" for s in FE_SCENES)
ALL_TARGETS.append("results/notebooks/section_09_12_beam_on_disc.html")
