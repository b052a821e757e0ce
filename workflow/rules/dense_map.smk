# Dense parameter maps (issue 7): a grid of exact-solver runs split into chunks, one job per chunk, merged
# into one netCDF per map with the swept parameters as dimensions. Sizes live in config/dense_map.yaml.
import importlib.util

from snakemake.utils import validate

validate(config, "../schemas/dense_map.schema.yaml")


def _load_dense_map_common():
    path = Path(workflow.basedir) / "workflow" / "scripts" / "dense_map_common.py"
    spec = importlib.util.spec_from_file_location("dense_map_common", path)
    loaded = importlib.util.module_from_spec(spec)
    sys.modules["dense_map_common"] = loaded  # dataclasses look their module up there
    spec.loader.exec_module(loaded)
    return loaded


# Parse every map now: a bad axis, parameter or chunk size fails here, naming its config key.
_dense_map_common = _load_dense_map_common()
DENSE_MAPS = {name: _dense_map_common.dense_map(config, name) for name in config["dense_map"]["maps"]}
DENSE_RESOURCES = config["dense_map"]["resources"]


def dense_map_chunks(wildcards):
    return expand(
        "results/dense_map/chunks/{map}/{chunk}.nc",
        map=wildcards.map,
        chunk=range(DENSE_MAPS[wildcards.map].chunks),
    )


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
    threads: 1
    resources:
        **DENSE_RESOURCES.get("dense_map_chunk", {}),
    params:
        map=lambda wc: config["dense_map"]["maps"][wc.map],  # rerun when the map's config changes
        chunk_size=lambda wc: DENSE_MAPS[wc.map].chunk_size,
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
    threads: 1
    resources:
        **DENSE_RESOURCES.get("dense_map_merge", {}),
    params:
        map=lambda wc: config["dense_map"]["maps"][wc.map],
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
