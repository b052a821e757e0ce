# 1-DOF studies beyond single scenes: Fig. 4 (Eq. 6), the parameter sweeps of Figs. 10-14, the critical belt
# speed (Section 13) and the interpretation study (readings ranked by the claims they reproduce).
SWEEPS = ONEDOF.get("sweeps", {})
SWEEP_FIGURES = ONEDOF.get("sweep_figures", {})
SWEEP_METHODS = sorted({sw.get("method", BASELINE["method"]) for sw in SWEEPS.values()})
SWEEP_SCENES = sorted({sw.get("scene", BASELINE["scene"]) for sw in SWEEPS.values()})
CRITICAL = ONEDOF.get("critical_speed")


rule eq6_curve:
    """Fig. 4: Eq. 6 as printed and the dimensionally correct amplitude curve, with their peaks."""
    output:
        nc="results/onedof/fig04/eq6.nc",
        png="results/figures/fig04/eq6.png",
    log:
        "results/logs/eq6_curve/all.log",
    benchmark:
        "results/benchmarks/eq6_curve/all.tsv"
    conda:
        CONDA_ENV
    params:
        config=onedof_subconfig(BASELINE["reading"], BASELINE["scene"], BASELINE["method"], study="eq6"),
        ensemble=ENSEMBLE,
    script:
        "../scripts/eq6_curve.py"


rule onedof_sweeps:
    """Every sweep for one reading, in one job (each run takes milliseconds; jobs cost seconds)."""
    output:
        [sweep_dataset(s, "{reading}", d) for s in SWEEPS for d in (False, True)],
    log:
        "results/logs/onedof_sweeps/{reading}.log",
    benchmark:
        "results/benchmarks/onedof_sweeps/{reading}.tsv"
    wildcard_constraints:
        reading="|".join(ONEDOF["readings"]),
    priority: PRIORITY["onedof_sweeps"]
    conda:
        CONDA_ENV
    params:
        config=lambda wc: onedof_subconfig(wc.reading, SWEEP_SCENES, SWEEP_METHODS, study="sweeps"),
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
            [sweep_dataset(_spec["sweep"], r, d) for r in _spec["readings"] for d in (False, True)],
        output:
            [f"results/figures/{_figure}/{r}.png" for r in _spec["readings"]],
        log:
            f"results/logs/sweep_figure/{_figure}.log",
        benchmark:
            f"results/benchmarks/sweep_figure/{_figure}.tsv"
        conda:
            CONDA_ENV
        params:
            title=_spec.get("title", _figure),
            readings=_spec["readings"],
            datasets={
                r: [sweep_dataset(_spec["sweep"], r, d) for d in (False, True)] for r in _spec["readings"]
            },
        script:
            "../scripts/plot_sweep_figure.py"


rule critical_speed:
    """Continuation over belt speed with the exact solver, every reading in one job."""
    output:
        expand("results/onedof/critical_speed/{reading}.nc", reading=CRITICAL["readings"] if CRITICAL else []),
    log:
        "results/logs/critical_speed/all.log",
    benchmark:
        "results/benchmarks/critical_speed/all.tsv"
    conda:
        CONDA_ENV
    params:
        config=onedof_subconfig(
            CRITICAL["readings"] if CRITICAL else [],
            BASELINE["scene"],
            BASELINE["method"],
            study="critical_speed",
        ),
        readings=CRITICAL["readings"] if CRITICAL else [],
        ensemble=ENSEMBLE,
        ensemble_outputs=sorted(
            CLAIMED_DATASETS
            & {f"results/onedof/critical_speed/{r}.nc" for r in (CRITICAL["readings"] if CRITICAL else [])}
        ),
    script:
        "../scripts/critical_speed.py"


rule critical_speed_summary:
    input:
        expand("results/onedof/critical_speed/{reading}.nc", reading=CRITICAL["readings"] if CRITICAL else []),
    output:
        csv="results/onedof/critical_speed.csv",
        nc="results/onedof/critical_speed.nc",
        png="results/figures/critical_speed/all.png",
    log:
        "results/logs/critical_speed_summary/all.log",
    benchmark:
        "results/benchmarks/critical_speed_summary/all.tsv"
    conda:
        CONDA_ENV
    params:
        readings=CRITICAL["readings"] if CRITICAL else [],
    script:
        "../scripts/critical_speed_summary.py"


rule reading_ranking:
    """Interpretation study: per reading, how many claims it reproduces / deviates / cannot compare."""
    input:
        "results/claims/deviations.csv",
    output:
        csv="results/claims/reading_ranking.csv",
        nc="results/claims/reading_ranking.nc",
        unreproduced="results/claims/unreproduced_claims.csv",
    log:
        "results/logs/reading_ranking/all.log",
    benchmark:
        "results/benchmarks/reading_ranking/all.tsv"
    conda:
        CONDA_ENV
    params:
        readings=config["claims"]["readings"],
    script:
        "../scripts/reading_ranking.py"


ALL_TARGETS.append("results/onedof/fig04/eq6.nc")
ALL_TARGETS.extend(
    sweep_dataset(s, r, d) for s in SWEEPS for r in config["claims"]["readings"] for d in (False, True)
)
ALL_TARGETS.extend(
    f"results/figures/{f}/{r}.png" for f, spec in SWEEP_FIGURES.items() for r in spec["readings"]
)
if CRITICAL:
    ALL_TARGETS.append("results/onedof/critical_speed.csv")
ALL_TARGETS.append("results/claims/reading_ranking.csv")
