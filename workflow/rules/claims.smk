# The claims table: every reported number vs what the pipeline measures, with pinned statuses.
CLAIM_READINGS = CFG.claims.readings  # checked against onedof.readings by stickslip.pipeline.config


rule claims_table:
    input:
        claims=CLAIM_FILES,
        datasets=sorted(CLAIMED_DATASETS),
        # which beam-on-disc rows the beam may decide (stickslip.claims.models)
        comparison=paths.fe_model_comparison("csv"),
    output:
        **outputs("claims_table", flags={"csv": report_of("Claims", "table")}),
    log:
        paths.log("claims_table"),
    benchmark:
        paths.benchmark("claims_table", "all")
    conda:
        CONDA_ENV
    params:
        claims=CLAIMS,  # the claim rows as the parse read them: the files stay inputs, for their dates
        readings=CLAIM_READINGS,
        # a cross-scene ratio of beam values is checked through its two scenes (stickslip.claims.models)
        cross_scene=as_params(CFG.fe.cross_scene),
    script:
        "../scripts/claims_table.py"


rule claims_check:
    """Fails when a measured status differs from the one pinned in the claims files, or a decision flips when
    the claimed metrics move within their perturbation-ensemble range (stickslip.claims.flips)."""
    input:
        table=paths.claims_table(),
        claims=CLAIM_FILES,
        datasets=sorted(CLAIMED_DATASETS),
        comparison=paths.fe_model_comparison("csv"),
    output:
        **outputs("claims_check", flags={"flag": touch}),
    log:
        paths.log("claims_check"),
    benchmark:
        paths.benchmark("claims_check", "all")
    conda:
        CONDA_ENV
    params:
        claims=CLAIMS,  # the claim rows as the parse read them: the files stay inputs, for their dates
        readings=CLAIM_READINGS,
        cross_scene=as_params(CFG.fe.cross_scene),
    script:
        "../scripts/claims_check.py"


ALL_TARGETS.append(paths.claims_table())
if CFG.claims.check:  # the small CI config measures other numbers: no pins apply
    ALL_TARGETS.append(paths.claims_check())
