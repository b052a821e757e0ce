# Cost of the whole pipeline: wall time and peak memory of every job, tabulated per rule.
# Named zz_ so it is included last and sees every other rule's targets.

#: every job's benchmark table is under this folder (never a target of the summary itself)
BENCHMARKS = str(Path(paths.benchmark_summary()).parent) + "/"


rule benchmark_summary:
    input:
        [t for t in ALL_TARGETS if not t.startswith(BENCHMARKS)],
    output:
        **outputs("benchmark_summary"),
    log:
        paths.log("benchmark_summary"),
    conda:
        CONDA_ENV
    params:
        root=lambda wc, output: str(Path(output.csv).parent),
    script:
        "../scripts/benchmark_summary.py"


ALL_TARGETS.append(paths.benchmark_summary("csv"))
