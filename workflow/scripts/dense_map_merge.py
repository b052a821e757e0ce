"""Thin wiring: merge a dense map's chunks into one dataset with the swept parameters as dimensions."""

import logging

from stickslip.analysis.sweep import align_chunks, merge_chunks
from stickslip.io.netcdf import read_dataset, write_dataset
from stickslip.io.progress import log_to_file
from stickslip.studies.specs import dense_map_job

log_to_file(snakemake.log[0])  # noqa: F821
dm = dense_map_job(snakemake.params.config, snakemake.wildcards.map)  # noqa: F821
chunks = align_chunks([read_dataset(path) for path in snakemake.input])  # noqa: F821
ds = merge_chunks(dm.axes, chunks)
failed = int((ds.solver_ok.values != 1).sum())
ds.attrs["failed_runs"] = failed
logging.info("merged %d chunks into %s, %d failed runs", len(chunks), dict(ds.sizes), failed)
write_dataset(
    ds,
    snakemake.output[0],
    scene=dm.scene_attrs(),
    interpretation=dm.spec.interpretation(),  # noqa: F821
    method=dm.method_attrs(),
    title=dm.title,
)
