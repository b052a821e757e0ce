"""Thin wiring: Fig. 4, Eq. 6 as printed and dimensionally correct, peaks in closed form."""

import matplotlib

matplotlib.use("Agg")

from stickslip.io.netcdf import write_dataset  # noqa: E402
from stickslip.presentation.plots import eq6_figure  # noqa: E402
from stickslip.schema import OnedofJob  # noqa: E402
from stickslip.studies.onedof import eq6_from_config  # noqa: E402
from stickslip.studies.specs import baseline_spec, job_dataset  # noqa: E402

params = snakemake.params  # noqa: F821
onedof = OnedofJob.model_validate(params.config).onedof
ds = job_dataset(eq6_from_config, params.config, params.ensemble, snakemake.output.nc)
write_dataset(
    ds,
    snakemake.output.nc,
    scene=baseline_spec(onedof).scene_attrs(),
    interpretation={
        "equation": "Eq. 6 as printed and dimensionally correct",
        "force": onedof.eq6.force,
        "units": "as_given (and si for the *_si peak)",
    },
    method={"name": "closed form"},
    title="Fig. 4: frequency-amplitude curve of Eq. 6",
)
eq6_figure(ds).savefig(snakemake.output.png, dpi=110)
