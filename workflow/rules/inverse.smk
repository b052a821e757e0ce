# The inverse study (a fit beside the claims table; it changes no pinned claim).
# `inverse.long: true` in config/inverse.yaml gives the long run (longer chains, exact leave-one-out refits).


rule inverse_study:
    input:
        claims=sorted(str(p) for p in Path(".").glob(CFG.inverse.claims_glob)),
    output:
        **outputs("inverse_study"),
    log:
        paths.log("inverse_study"),
    benchmark:
        paths.benchmark("inverse_study")
    priority: PRIORITY["inverse_study"]
    conda:
        CONDA_ENV
    params:
        # the inverse section as written: a hypothesis is named by its first key, listed in file order
        config={"onedof": inverse_onedof_config(), "inverse": as_written(CFG.inverse)},
    script:
        "../scripts/inverse_study.py"


ALL_TARGETS.extend(rules.inverse_study.output)
