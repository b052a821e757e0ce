"""Thin wiring: every parameter sweep (Figs. 10-14, belt speed) for one reading (Snakemake script).

Per sweep two datasets: the paper's values (metrics + time series) and a dense version (>= 50 points,
metrics only), from stickslip.studies.onedof.sweep_dataset; the claimed ones carry a perturbation ensemble."""

import logging
from functools import partial

from stickslip.io.progress import Progress, log_to_file
from stickslip.schema import OnedofJob
from stickslip.studies.onedof import sweep_from_config
from stickslip.studies.specs import job_dataset, sweep_spec

log_to_file(snakemake.log[0])  # noqa: F821
reading, params = snakemake.wildcards.reading, snakemake.params  # noqa: F821
onedof = OnedofJob.model_validate(params.config).onedof
for (sweep, dense), path in zip(params.runs, snakemake.output, strict=True):  # noqa: F821
    name = f"{sweep}_dense" if dense else sweep
    spec = sweep_spec(onedof, sweep, reading)
    progress = partial(Progress, f"sweep {name}", sink=logging.info)
    build = partial(sweep_from_config, sweep=sweep, reading=reading, dense=dense, progress=progress)
    ds = job_dataset(build, params.config, params.ensemble, path, path in params.ensemble_outputs)
    spec.base.write(
        ds,
        path,
        f"{spec.figure} sweep over {spec.parameter} ({ds.attrs['sweep_kind']}), reading {reading}",
        scene={"sweep": spec.name, "parameter": spec.parameter},
    )
    logging.info("%s: %d points, %d failed", path, ds.sizes[spec.parameter], ds.attrs["failed_runs"])
