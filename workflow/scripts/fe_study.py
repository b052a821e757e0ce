"""Convergence study or stability map (params.kind) -> netCDF."""
from fe_common import log_to, write_dataset

from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import INTERPRETATION, convergence_dataset, stability_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
kind = snakemake.params.kind  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
ds = (convergence_dataset if kind == "convergence" else stability_dataset)(cfg, friction)
print(ds)
write_dataset(ds, snakemake.output[0], scene=dict(cfg[kind]), interpretation=INTERPRETATION,  # noqa: F821
              method={"study": kind})
