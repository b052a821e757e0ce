# Dense parameter maps (issue 7): a grid of exact-solver runs split into chunks, one job per chunk, merged
# into one netCDF per map with the swept parameters as dimensions. Sizes live in config/dense_map.yaml.
from stickslip.studies.specs import dense_map

DENSE_MAPS = {name: dense_map(config, name) for name in config["dense_map"]["maps"]}
DENSE_RESOURCES = config["dense_map"]["resources"]


rule dense_map_chunk:
    """Metrics of one contiguous slice of a map's grid (flattened C order)."""
    output:
        temp("results/dense_map/chunks/{map}/{chunk}.nc"),
    log:
        "results/logs/dense_map_chunk/{map}/{chunk}.log",
    benchmark:
        "results/benchmarks/dense_map_chunk/{map}/{chunk}.tsv"
    wildcard_constraints:
        map="|".join(DENSE_MAPS),
        chunk=r"\d+",
    conda:
        CONDA_ENV
    threads: 1
    resources:
        **DENSE_RESOURCES.get("dense_map_chunk", {}),
    params:
        config=lambda wc: dense_map_subconfig(wc.map),  # rerun when anything the map reads changes
    script:
        "../scripts/dense_map_chunk.py"


rule dense_map_merge:
    """All chunks of a map as one dataset with one dimension per swept parameter."""
    input:
        dense_map_chunks,
    output:
        "results/dense_map/{map}.nc",
    log:
        "results/logs/dense_map_merge/{map}.log",
    benchmark:
        "results/benchmarks/dense_map_merge/{map}.tsv"
    wildcard_constraints:
        map="|".join(DENSE_MAPS),
    conda:
        CONDA_ENV
    threads: 1
    resources:
        **DENSE_RESOURCES.get("dense_map_merge", {}),
    params:
        config=lambda wc: dense_map_subconfig(wc.map),
    script:
        "../scripts/dense_map_merge.py"


rule dense_map_figure:
    """One panel per metric over the two first swept parameters; failed runs are masked, not plotted."""
    input:
        "results/dense_map/{map}.nc",
    output:
        "results/figures/dense_map/{map}.png",
    log:
        "results/logs/dense_map_figure/{map}.log",
    benchmark:
        "results/benchmarks/dense_map_figure/{map}.tsv"
    wildcard_constraints:
        map="|".join(DENSE_MAPS),
    conda:
        CONDA_ENV
    threads: 1
    resources:
        **DENSE_RESOURCES.get("dense_map_figure", {}),
    params:
        plot=lambda wc: list(DENSE_MAPS[wc.map].plot),
        title=lambda wc: DENSE_MAPS[wc.map].title,
    script:
        "../scripts/dense_map_figure.py"


ALL_TARGETS.extend(f"results/dense_map/{name}.nc" for name in DENSE_MAPS)
ALL_TARGETS.extend(f"results/figures/dense_map/{name}.png" for name in DENSE_MAPS)
