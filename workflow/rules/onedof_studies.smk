# 1-DOF studies beyond single scenes: Fig. 4 (Eq. 6), the parameter sweeps of Figs. 10-14, the critical belt
# speed (Section 13) and the interpretation study (readings ranked by the claims they reproduce).
from stickslip.io.scenes import sweep_spec

SWEEPS = ONEDOF.get("sweeps", {})
SWEEP_FIGURES = ONEDOF.get("sweep_figures", {})
CRITICAL = ONEDOF.get("critical_speed")

# Resolve every sweep for every claims reading at parse time: a bad sweep fails naming its key.
for _sw in SWEEPS:
    for _r in config["claims"]["readings"]:
        sweep_spec(config, _sw, _r)


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
        config=onedof_subconfig(),
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
    conda:
        CONDA_ENV
    params:
        config=lambda wc: onedof_subconfig(wc.reading),
    script:
        "../scripts/onedof_sweeps.py"


rule sweep_figure:
    input:
        paper=lambda wc: sweep_dataset(SWEEP_FIGURES[wc.figure]["sweep"], wc.reading),
        dense=lambda wc: sweep_dataset(SWEEP_FIGURES[wc.figure]["sweep"], wc.reading, True),
    output:
        "results/figures/{figure}/{reading}.png",
    log:
        "results/logs/sweep_figure/{figure}/{reading}.log",
    benchmark:
        "results/benchmarks/sweep_figure/{figure}/{reading}.tsv"
    wildcard_constraints:
        figure="|".join(SWEEP_FIGURES) or "none",
    conda:
        CONDA_ENV
    params:
        title=lambda wc: SWEEP_FIGURES[wc.figure].get("title", wc.figure),
    script:
        "../scripts/plot_sweep_figure.py"


rule critical_speed:
    """Continuation over belt speed with the exact solver for one reading."""
    output:
        "results/onedof/critical_speed/{reading}.nc",
    log:
        "results/logs/critical_speed/{reading}.log",
    benchmark:
        "results/benchmarks/critical_speed/{reading}.tsv"
    wildcard_constraints:
        reading="|".join(ONEDOF["readings"]),
    conda:
        CONDA_ENV
    params:
        config=lambda wc: onedof_subconfig(wc.reading),
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
