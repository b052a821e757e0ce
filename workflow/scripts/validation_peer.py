"""Thin wiring: the switch-model solver against CVODE (and the Coulomb closed form), every configured law."""

from stickslip.io.netcdf import write_dataset
from stickslip.schema import PeerJob, given
from stickslip.validation.compare import peer_comparison
from stickslip.validation.datasets import peer_dataset, write_csv
from stickslip.validation.setup import law_model, switch_solver

job = PeerJob.model_validate(snakemake.params.validation)  # noqa: F821
solver = switch_solver(job.solver, "validation.solver")
tolerances = dict(job.tolerances)
rows, runs = [], {}
for name, csv_path in zip(job.laws, snakemake.output.csv, strict=True):  # noqa: F821
    law_rows, runs[name] = peer_comparison(
        name,
        law_model(job, name),
        job.t_end,
        solver,
        job.peer,
        tolerances,
        job.laws[name].closed_form,
    )
    write_csv(law_rows, csv_path)
    rows += law_rows
write_dataset(
    peer_dataset(rows, runs, tolerances),
    snakemake.output.nc,  # noqa: F821
    scene={
        "base_params": given(job.base_params),
        "t_end": job.t_end,
        "laws": {name: given(entry) for name, entry in job.laws.items()},
    },
    interpretation="friction opposes the relative velocity (consistent sign); paper numbers used as given",
    method={"switch": solver.settings, "peer": given(job.peer)},
    title="Switch-model solver vs SUNDIALS CVODE and the Coulomb closed form: last-cycle quantities",
)
