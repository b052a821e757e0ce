"""Snakemake script: failure map over (parameter value, method setting)."""

from stickslip.io.netcdf import write_dataset
from stickslip.schema import MethodsStudy, given
from stickslip.studies.methods import INTERPRETATION, failure_map_dataset

study = MethodsStudy.model_validate(snakemake.params.study)  # noqa: F821
fm = study.failure_map
write_dataset(
    failure_map_dataset(study),
    snakemake.output[0],  # noqa: F821
    scene={"name": fm.scene, "sweep": fm.parameter, "values": fm.values},
    interpretation=INTERPRETATION,
    method={
        "reference": "exact",
        "methods": [given(m) for m in fm.methods],
        "budget": study.budget.model_dump(),
    },
)
