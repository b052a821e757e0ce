"""Thin wiring: run one chunk of a dense map and write its metrics over the flattened grid index."""

import logging
import time

from stickslip.analysis.sweep import chunk_dataset, chunk_points
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import Progress, log_to_file
from stickslip.studies.specs import dense_map_job

log_to_file(snakemake.log[0])  # noqa: F821
name, chunk = snakemake.wildcards.map, int(snakemake.wildcards.chunk)  # noqa: F821
dm = dense_map_job(snakemake.params.config, name)  # noqa: F821
points = chunk_points(dm.axes, dm.chunk_size, chunk)
logging.info("map %s chunk %d/%d: %d of %d grid points", name, chunk + 1, dm.chunks, len(points), dm.points)
start = time.perf_counter()
results = dm.run(
    points,
    progress=Progress(f"map {name} chunk {chunk}", every=5.0, sink=logging.info),
)
ds = chunk_dataset(dm.axes, dm.chunk_size, chunk, results)
failed = int((ds.solver_ok.values != 1).sum())
if failed:
    logging.warning("%d of %d runs failed (NaN metrics, solver_ok = 0)", failed, len(points))
write_dataset(
    ds,
    snakemake.output[0],
    scene=dm.scene_attrs(),
    interpretation=dm.spec.interpretation(),  # noqa: F821
    method={**dm.method_attrs(), "chunk": chunk},
    title=f"{dm.title}: chunk {chunk}",
)
logging.info(
    "done: %.2f s, %.2f ms per point",
    time.perf_counter() - start,
    1e3 * (time.perf_counter() - start) / len(points),
)
