# The inverse study (a fit beside the claims table; it changes no pinned claim).
# `inverse.long: true` in config/inverse.yaml gives the long run (longer chains, exact leave-one-out refits).

INVERSE_FIGURES = list(config["inverse"]["figures"]) + ["joint"]
INVERSE_FAMILIES = list(config["inverse"]["families"])
INVERSE_MODE = "long" if config["inverse"].get("long", False) else "default"
INVERSE_CORNER = config["inverse"]["settings"][INVERSE_MODE].get("corner", [])


rule inverse_study:
    input:
        claims=sorted(str(p) for p in Path(".").glob(config["inverse"]["claims_glob"])),
    output:
        summary="results/inverse/summary.csv",
        hypotheses="results/inverse/hypotheses.csv",
        ranking="results/inverse/ranking.csv",
        numbers="results/inverse/numbers.csv",
        conflicts="results/inverse/conflicts.csv",
        datasets=expand("results/inverse/{figure}.nc", figure=INVERSE_FIGURES),
        corner=expand(
            "results/inverse/corner/{figure}_{family}.png",
            figure=INVERSE_CORNER,
            family=INVERSE_FAMILIES,
        ),
    log:
        "results/logs/inverse_study.log",
    benchmark:
        "results/benchmarks/inverse_study.tsv"
    priority: PRIORITY["inverse_study"]
    conda:
        CONDA_ENV
    params:
        config={
            "onedof": {k: ONEDOF[k] for k in ("baseline", "defaults", "scenes", "sweeps")},
            "inverse": config["inverse"],
        },
    script:
        "../scripts/inverse_study.py"


ALL_TARGETS.extend(rules.inverse_study.output)
