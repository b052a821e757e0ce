"""Run a parameter sweep of the beam-on-disc scene and write results/fe/<sweep>.nc."""

import stickslip.fe.pipeline as fe_pipeline
from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import INTERPRETATION, sweep_dataset

from fe_common import log_to, track_calls, write_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
name = snakemake.wildcards.sweep  # noqa: F821
# one run_scene per swept value: log done/total, elapsed and ETA as they complete
progress = track_calls(fe_pipeline, "run_scene", len(cfg["sweeps"][name]["values"]), label=name, every=5.0)
ds = sweep_dataset(cfg, name, FrictionTable.from_csv(snakemake.input.friction))  # noqa: F821
progress.finish()
print(ds)
write_dataset(
    ds,
    snakemake.output[0],  # noqa: F821
    scene=dict(cfg["sweeps"][name]),
    interpretation=INTERPRETATION,
    method={"integrator": "central_difference", "sweep": name},
)
