# Dense parameter maps (issue 7): a grid of exact-solver runs split into chunks, one job per chunk, merged
# into one netCDF per map with the swept parameters as dimensions. Sizes live in config/dense_map.yaml.
from stickslip.studies.specs import dense_map_job

#: Each map as its jobs resolve it, from the params they are given (dense_map_subconfig).
DENSE_MAPS = {name: dense_map_job(dense_map_subconfig(name), name) for name in CFG.dense_map.maps}
DENSE_RESOURCES = CFG.dense_map.resources


rule dense_map_chunk:
    """Metrics of one contiguous slice of a map's grid (flattened C order)."""
    output:
        temp(paths.dense_map_chunk("{map}", "{chunk}")),
    log:
        paths.log("dense_map_chunk", "{map}/{chunk}"),
    benchmark:
        paths.benchmark("dense_map_chunk", "{map}/{chunk}")
    wildcard_constraints:
        map="|".join(DENSE_MAPS),
        chunk=r"\d+",
    conda:
        CONDA_ENV
    threads: 1
    resources:
        **(as_params(DENSE_RESOURCES.dense_map_chunk) or {}),
    params:
        config=lambda wc: dense_map_subconfig(wc.map),  # rerun when anything the map reads changes
    script:
        "../scripts/dense_map_chunk.py"


rule dense_map_merge:
    """All chunks of a map as one dataset with one dimension per swept parameter."""
    input:
        lambda wc: [paths.dense_map_chunk(wc.map, c) for c in range(DENSE_MAPS[wc.map].chunks)],
    output:
        **outputs("dense_map_merge", name="{map}"),
    log:
        paths.log("dense_map_merge", "{map}"),
    benchmark:
        paths.benchmark("dense_map_merge", "{map}")
    wildcard_constraints:
        map="|".join(DENSE_MAPS),
    conda:
        CONDA_ENV
    threads: 1
    resources:
        **(as_params(DENSE_RESOURCES.dense_map_merge) or {}),
    params:
        config=lambda wc: dense_map_subconfig(wc.map),
    script:
        "../scripts/dense_map_merge.py"


rule dense_map_figure:
    """One panel per metric over the two first swept parameters; failed runs are masked, not plotted."""
    input:
        paths.dense_map("{map}"),
    output:
        **outputs("dense_map_figure", name="{map}"),
    log:
        paths.log("dense_map_figure", "{map}"),
    benchmark:
        paths.benchmark("dense_map_figure", "{map}")
    wildcard_constraints:
        map="|".join(DENSE_MAPS),
    conda:
        CONDA_ENV
    threads: 1
    resources:
        **(as_params(DENSE_RESOURCES.dense_map_figure) or {}),
    params:
        plot=lambda wc: list(DENSE_MAPS[wc.map].plot),
        title=lambda wc: DENSE_MAPS[wc.map].title,
    script:
        "../scripts/dense_map_figure.py"


ALL_TARGETS.extend(products_of("dense_map_merge", "dense_map_figure"))
