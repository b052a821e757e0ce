# 1-DOF studies beyond single scenes: Fig. 4 (Eq. 6), the parameter sweeps of Figs. 10-14, the critical belt
# speed (Section 13) and the interpretation study (readings ranked by the claims they reproduce).
BASE = CFG.onedof.baseline
SWEEPS, SWEEP_FIGURES = CFG.onedof.sweeps, CFG.onedof.sweep_figures
SWEEP_METHODS = sorted({sw.method or BASE.method for sw in SWEEPS.values()})
SWEEP_SCENES = sorted({sw.scene or BASE.scene for sw in SWEEPS.values()})
CRITICAL_READINGS = critical_speed_readings()


rule eq6_curve:
    """Fig. 4: Eq. 6 as printed and the dimensionally correct amplitude curve, with their peaks."""
    output:
        **outputs("eq6_curve"),
    log:
        paths.log("eq6_curve", "all"),
    benchmark:
        paths.benchmark("eq6_curve", "all")
    conda:
        CONDA_ENV
    params:
        config=onedof_subconfig(BASE.reading, BASE.scene, BASE.method, study="eq6"),
        ensemble=ENSEMBLE,
    script:
        "../scripts/eq6_curve.py"


rule onedof_sweeps:
    """Every sweep for one reading, in one job (each run takes milliseconds; jobs cost seconds)."""
    output:
        **outputs("onedof_sweeps", reading="{reading}"),
    log:
        paths.log("onedof_sweeps", "{reading}"),
    benchmark:
        paths.benchmark("onedof_sweeps", "{reading}")
    wildcard_constraints:
        reading="|".join(CFG.onedof.readings),
    priority: PRIORITY["onedof_sweeps"]
    conda:
        CONDA_ENV
    params:
        config=lambda wc: onedof_subconfig(wc.reading, SWEEP_SCENES, SWEEP_METHODS, study="sweeps"),
        # (sweep, dense) of each output, in the same order
        runs=[[s, d] for s in SWEEPS for d in (False, True)],
        ensemble=ENSEMBLE,
        ensemble_outputs=lambda wc: sorted(
            CLAIMED_DATASETS & {sweep_dataset(s, wc.reading, d) for s in SWEEPS for d in (False, True)}
        ),
    script:
        "../scripts/onedof_sweeps.py"


for _figure, _spec in SWEEP_FIGURES.items():

    rule:
        """Figs. 10-14: the paper's curves beside the dense sweep's metrics, every reading in one job."""
        name:
            f"sweep_figure_{_figure}"
        input:
            [sweep_dataset(_spec.sweep, r, d) for r in _spec.readings for d in (False, True)],
        output:
            **outputs(f"sweep_figure_{_figure}"),
        log:
            paths.log("sweep_figure", _figure),
        benchmark:
            paths.benchmark("sweep_figure", _figure)
        conda:
            CONDA_ENV
        params:
            title=_spec.title or _figure,
            readings=_spec.readings,
            datasets={r: [sweep_dataset(_spec.sweep, r, d) for d in (False, True)] for r in _spec.readings},
        script:
            "../scripts/plot_sweep_figure.py"


rule critical_speed:
    """Continuation over belt speed with the exact solver, every reading in one job."""
    output:
        **outputs("critical_speed"),
    log:
        paths.log("critical_speed", "all"),
    benchmark:
        paths.benchmark("critical_speed", "all")
    conda:
        CONDA_ENV
    params:
        config=onedof_subconfig(CRITICAL_READINGS, BASE.scene, BASE.method, study="critical_speed"),
        ensemble=ENSEMBLE,
        ensemble_outputs=sorted(CLAIMED_DATASETS & set(products_of("critical_speed"))),
    script:
        "../scripts/critical_speed.py"


rule critical_speed_summary:
    input:
        products_of("critical_speed"),
    output:
        **outputs("critical_speed_summary"),
    log:
        paths.log("critical_speed_summary", "all"),
    benchmark:
        paths.benchmark("critical_speed_summary", "all")
    conda:
        CONDA_ENV
    params:
        readings=CRITICAL_READINGS,
    script:
        "../scripts/critical_speed_summary.py"


rule reading_ranking:
    """Interpretation study: per reading, how many claims it reproduces / deviates / cannot compare."""
    input:
        paths.claims_table(),
    output:
        **outputs("reading_ranking"),
    log:
        paths.log("reading_ranking", "all"),
    benchmark:
        paths.benchmark("reading_ranking", "all")
    conda:
        CONDA_ENV
    params:
        readings=CFG.claims.readings,
    script:
        "../scripts/reading_ranking.py"


ALL_TARGETS.append(paths.eq6_curve())
ALL_TARGETS.extend(sweep_dataset(s, r, d) for s in SWEEPS for r in CFG.claims.readings for d in (False, True))
ALL_TARGETS.extend(products_of(*(f"sweep_figure_{fig}" for fig in SWEEP_FIGURES)))
if CFG.onedof.critical_speed is not None:
    ALL_TARGETS.append(paths.critical_speed_summary("csv"))
ALL_TARGETS.append(paths.reading_ranking("csv"))
