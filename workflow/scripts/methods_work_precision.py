"""Snakemake script: work-precision data of every method on one scene."""

from stickslip.io.netcdf import write_dataset
from stickslip.schema import MethodsStudy, given
from stickslip.studies.methods import INTERPRETATION, work_precision_dataset

study = MethodsStudy.model_validate(snakemake.params.study)  # noqa: F821
scene = snakemake.wildcards.scene  # noqa: F821
ds, model = work_precision_dataset(study, scene)
write_dataset(
    ds,
    snakemake.output[0],  # noqa: F821
    scene={"name": scene, **model.params.as_dict(), "variant": model.variant},
    interpretation=INTERPRETATION,
    method={
        "reference": "exact",
        "paper_method": given(study.paper_method),
        "budget": study.budget.model_dump(),
        "timing": study.timing.model_dump(),
    },
)
