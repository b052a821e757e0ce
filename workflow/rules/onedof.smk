# 1-DOF mass on a moving belt: one dataset per scene x reading x method, one rule per paper figure kind.


for _scene, _runs in onedof_runs().items():

    rule:
        """Every reading x method of one scene that a figure, claim or notebook reads, in one job."""
        name:
            f"simulate_onedof_{_scene}"
        output:
            [onedof_dataset(_scene, r, m) for r, m in _runs],
        log:
            paths.log("simulate_onedof", _scene),
        benchmark:
            paths.benchmark("simulate_onedof", _scene)
        conda:
            CONDA_ENV
        params:
            scene=_scene,
            runs=_runs,
            configs=[onedof_subconfig(r, _scene, m) for r, m in _runs],  # what each run reads and perturbs
            ensemble=ENSEMBLE,
            ensemble_outputs=sorted(CLAIMED_DATASETS & {onedof_dataset(_scene, r, m) for r, m in _runs}),
        script:
            "../scripts/simulate_onedof.py"


for _figure, _spec in CFG.onedof.figures.items():

    rule:
        """One paper figure (time series, phase plot or velocity) for every reading, methods overlaid."""
        name:
            f"onedof_figure_{_figure}"
        input:
            figure_datasets(_figure),
        output:
            **outputs(f"onedof_figure_{_figure}"),
        log:
            paths.log("onedof_figure", _figure),
        benchmark:
            paths.benchmark("onedof_figure", _figure)
        conda:
            CONDA_ENV
        params:
            figure=as_params(_spec),
            datasets={
                r: {m: onedof_dataset(_spec.scene, r, m) for m in _spec.methods} for r in _spec.readings
            },
        script:
            "../scripts/plot_onedof_figure.py"


ALL_TARGETS.extend(products_of(*(f"onedof_figure_{fig}" for fig in CFG.onedof.figures)))


rule friction_table:
    """Fig. 17: mu(v_r) along the baseline solution; the beam-on-disc (FE) scenes use it as their friction law."""
    output:
        **outputs("friction_table"),
    log:
        paths.log("friction_table", "all"),
    benchmark:
        paths.benchmark("friction_table", "all")
    priority: PRIORITY["friction_table"]
    conda:
        CONDA_ENV
    params:
        config=onedof_subconfig(TABLE_RUN.reading, TABLE_RUN.scene, TABLE_RUN.method, study="friction_table"),
        ensemble=ENSEMBLE,
    script:
        "../scripts/friction_table.py"


ALL_TARGETS.append(paths.friction_table("csv"))
