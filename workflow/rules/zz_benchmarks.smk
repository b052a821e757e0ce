# Cost of the whole pipeline: wall time and peak memory of every job, tabulated per rule.
# Named zz_ so it is included last and sees every other rule's targets.


rule benchmark_summary:
    input:
        [t for t in ALL_TARGETS if not t.startswith("results/benchmarks/")],
    output:
        csv="results/benchmarks/summary.csv",
        md="results/benchmarks/summary.md",
    log:
        "results/logs/benchmark_summary.log",
    conda:
        CONDA_ENV
    params:
        root=lambda wc, output: str(Path(output.csv).parent),
    script:
        "../scripts/benchmark_summary.py"


ALL_TARGETS.append("results/benchmarks/summary.csv")
