# Captions for `snakemake --report results/report.html`: every figure with the paper figure it reproduces
# and the statuses of its claims (read from the deviations table of the same run).


rule report_captions:
    input:
        table="results/claims/deviations.csv",
        figures=str(Path(workflow.basedir) / "workflow" / "report" / "figures.yaml"),
    output:
        REPORT_CAPTIONS,
    log:
        "results/logs/report_captions/all.log",
    benchmark:
        "results/benchmarks/report_captions/all.tsv"
    conda:
        CONDA_ENV
    params:
        figures=lambda wc: sorted(ONEDOF["figures"]),  # rerun when the figure list changes
    script:
        "../scripts/report_captions.py"


ALL_TARGETS.append(REPORT_CAPTIONS)
