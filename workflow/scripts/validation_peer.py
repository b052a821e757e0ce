"""Thin wiring: the switch-model solver against CVODE (and the Coulomb closed form), every configured law."""

from stickslip.io.netcdf import write_dataset
from stickslip.validation.compare import peer_comparison
from stickslip.validation.datasets import peer_dataset, write_csv
from stickslip.validation.setup import ValidationSetup

setup = ValidationSetup(snakemake.params.validation)
tolerances = setup.tolerances()
rows, runs = [], {}
for name, csv_path in zip(setup.law_names(), snakemake.output.csv, strict=True):
    law_rows, runs[name] = peer_comparison(
        name,
        setup.model(name),
        setup.t_end,
        setup.solver(),
        setup.peer(),
        tolerances,
        setup.closed_form(name),
    )
    write_csv(law_rows, csv_path)
    rows += law_rows
write_dataset(
    peer_dataset(rows, runs, tolerances),
    snakemake.output.nc,
    scene={"base_params": setup.cfg["base_params"], "t_end": setup.t_end, "laws": setup.cfg["laws"]},
    interpretation="friction opposes the relative velocity (consistent sign); paper numbers used as given",
    method={"switch": setup.solver().settings, "peer": setup.cfg["peer"]},
    title="Switch-model solver vs SUNDIALS CVODE and the Coulomb closed form: last-cycle quantities",
)
