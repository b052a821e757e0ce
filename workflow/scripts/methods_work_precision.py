"""Snakemake script: work-precision data of every method on one scene."""

from stickslip.io.netcdf import write_dataset
from stickslip.studies.methods import INTERPRETATION, work_precision_dataset

cfg = snakemake.params.study  # noqa: F821
scene = snakemake.wildcards.scene  # noqa: F821
ds, model = work_precision_dataset(cfg, scene)
write_dataset(
    ds,
    snakemake.output[0],  # noqa: F821
    scene={"name": scene, **model.params.as_dict(), "variant": model.variant},
    interpretation=INTERPRETATION,
    method={
        "reference": "exact",
        "paper_method": cfg["paper_method"],
        "budget": cfg["budget"],
        "timing": cfg["timing"],
    },
)
