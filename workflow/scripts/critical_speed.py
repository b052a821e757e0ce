"""Thin wiring: continuation over belt speed -> critical speed, one dataset per reading (Snakemake script)."""

import logging
from functools import partial

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.io.netcdf import write_dataset
from stickslip.io.progress import log_to_file
from stickslip.studies.onedof import critical_speed_from_config
from stickslip.studies.specs import PERTURBED_FIELDS, baseline_spec

log_to_file(snakemake.log[0])  # noqa: F821
config = snakemake.params.config
ensemble = EnsembleSpec.from_mapping(snakemake.params.ensemble).without_blas()  # 1-DOF: no BLAS
for reading, path in zip(snakemake.params.readings, snakemake.output):
    spec = baseline_spec(config, reading)
    claimed = path in snakemake.params.ensemble_outputs
    ds = ensemble_dataset(
        partial(critical_speed_from_config, reading=reading),
        config,
        ensemble if claimed else None,
        run_id=path,
        fields=PERTURBED_FIELDS,
    )
    write_dataset(
        ds,
        path,
        scene=spec.scene_attrs() | {"continuation": "natural parameter, increasing V_b"},
        interpretation=spec.interpretation(),
        method={"name": spec.method, **spec.solver_settings},
        title=f"Critical belt speed, reading {reading}",
    )
    logging.info(
        "%s: critical speed %s mm/s; failures: %s", reading, float(ds.critical_belt_speed), ds.failures
    )
