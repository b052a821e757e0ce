"""Snakemake script: failure map over (parameter value, method setting)."""

from stickslip.io.netcdf import write_dataset
from stickslip.studies.methods import INTERPRETATION, failure_map_dataset

cfg = snakemake.params.study  # noqa: F821
fm = cfg["failure_map"]
write_dataset(
    failure_map_dataset(cfg),
    snakemake.output[0],  # noqa: F821
    scene={"name": fm["scene"], "sweep": fm["parameter"], "values": fm["values"]},
    interpretation=INTERPRETATION,
    method={"reference": "exact", "methods": fm["methods"], "budget": cfg["budget"]},
)
