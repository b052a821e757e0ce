# The claims table: every reported number vs what the pipeline measures, with pinned statuses.
CLAIM_READINGS = config["claims"]["readings"]  # checked against onedof.readings by stickslip.pipeline.config


rule claims_table:
    input:
        claims=CLAIM_FILES,
        datasets=sorted(CLAIMED_DATASETS),
        # which beam-on-disc rows the beam may decide (stickslip.claims.models)
        comparison="results/fe/model_comparison.csv",
    output:
        csv=report(
            "results/claims/deviations.csv",
            caption=REPORT_CAPTION_FILE,
            category="Claims",
            labels={"table": "deviations"},
        ),
        md="results/claims/deviations.md",
    log:
        "results/logs/claims_table.log",
    benchmark:
        "results/benchmarks/claims_table/all.tsv"
    conda:
        CONDA_ENV
    params:
        readings=CLAIM_READINGS,
    script:
        "../scripts/claims_table.py"


rule claims_check:
    """Fails when a measured status differs from the one pinned in the claims files."""
    input:
        "results/claims/deviations.csv",
    output:
        touch("results/claims/check.ok"),
    log:
        "results/logs/claims_check.log",
    benchmark:
        "results/benchmarks/claims_check/all.tsv"
    conda:
        CONDA_ENV
    script:
        "../scripts/claims_check.py"


ALL_TARGETS.append("results/claims/deviations.csv")
if config["claims"].get("check", True):  # the small CI config measures other numbers: no pins apply
    ALL_TARGETS.append("results/claims/check.ok")
