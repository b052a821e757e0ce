"""Run a parameter sweep of the beam-on-disc scene and write results/fe/<sweep>.nc."""
from fe_common import log_to, write_dataset

from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import INTERPRETATION, sweep_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
name = snakemake.wildcards.sweep  # noqa: F821
ds = sweep_dataset(cfg, name, FrictionTable.from_csv(snakemake.input.friction))  # noqa: F821
print(ds)
write_dataset(ds, snakemake.output[0], scene=dict(cfg["sweeps"][name]), interpretation=INTERPRETATION,  # noqa: F821
              method={"integrator": "central_difference", "sweep": name})
