# 1-DOF mass on a moving belt: one dataset per scene x reading x method, one rule per paper figure kind.


rule simulate_onedof:
    output:
        "results/onedof/{scene}/{reading}/{method}.nc",
    log:
        "results/logs/simulate_onedof/{scene}/{reading}/{method}.log",
    benchmark:
        "results/benchmarks/simulate_onedof/{scene}/{reading}/{method}.tsv"
    wildcard_constraints:
        scene="|".join(ONEDOF["scenes"]),
        reading="|".join(ONEDOF["readings"]),
        method="|".join(ONEDOF["methods"]),
    conda:
        CONDA_ENV
    params:
        config=lambda wc: onedof_subconfig(wc.reading, wc.scene, wc.method),
    script:
        "../scripts/simulate_onedof.py"


rule onedof_figure:
    """Time series (displacement and velocity, Fig. 2 style) or phase plot (Fig. 3 style) of one reading."""
    input:
        lambda wc: [
            onedof_dataset(ONEDOF["figures"][wc.figure]["scene"], wc.reading, m)
            for m in ONEDOF["figures"][wc.figure]["methods"]
        ],
    output:
        "results/figures/{figure}/{reading}.png",
    log:
        "results/logs/onedof_figure/{figure}/{reading}.log",
    benchmark:
        "results/benchmarks/onedof_figure/{figure}/{reading}.tsv"
    wildcard_constraints:
        figure="|".join(ONEDOF["figures"]),
    conda:
        CONDA_ENV
    params:
        figure=lambda wc: ONEDOF["figures"][wc.figure],
        methods=lambda wc: ONEDOF["figures"][wc.figure]["methods"],
    script:
        "../scripts/plot_onedof_figure.py"


ALL_TARGETS.extend(
    f"results/figures/{fig}/{reading}.png"
    for fig, spec in ONEDOF["figures"].items()
    for reading in spec["readings"]
)


# Resolve every run the figures need at parse time, so a bad scene/reading/method value fails before any
# job starts, with the offending key named (the schema cannot see e.g. NaN or an unknown solver setting).
from stickslip.io.scenes import figure_runs, run_spec

for _fig in ONEDOF["figures"]:
    for _scene, _reading, _method in figure_runs(config, _fig):
        run_spec(config, _scene, _reading, _method)


rule friction_table:
    """Fig. 17: mu(v_r) along the baseline solution; the beam-on-disc (FE) scenes use it as their friction law."""
    input:
        lambda wc: onedof_dataset(
            ONEDOF["friction_table"]["scene"],
            ONEDOF["friction_table"]["reading"],
            ONEDOF["friction_table"]["method"],
        ),
    output:
        csv="results/onedof/friction_mu_vr.csv",
        nc="results/onedof/friction_mu_vr.nc",
    log:
        "results/logs/friction_table/all.log",
    benchmark:
        "results/benchmarks/friction_table/all.tsv"
    conda:
        CONDA_ENV
    params:
        table=ONEDOF["friction_table"],
        config=onedof_subconfig(
            ONEDOF["friction_table"]["reading"],
            ONEDOF["friction_table"]["scene"],
            ONEDOF["friction_table"]["method"],
        ),
    script:
        "../scripts/friction_table.py"


ALL_TARGETS.append("results/onedof/friction_mu_vr.csv")
