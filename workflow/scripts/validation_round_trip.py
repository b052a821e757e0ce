"""Thin wiring: the 1-DOF model driven by the Fig. 17 table vs the cycle the table came from."""

import numpy as np

from stickslip.io.netcdf import read_dataset, write_dataset
from stickslip.model.laws import LawModel, TabulatedLaw, law_from_config
from stickslip.schema import FrictionTable, OnedofJob, RoundTrip, SwitchSettings
from stickslip.solvers.switch import SwitchSolver
from stickslip.studies.specs import run_spec
from stickslip.validation.compare import round_trip_cases
from stickslip.validation.datasets import round_trip_dataset, round_trip_rows, write_csv
from stickslip.validation.setup import switch_solver

params = snakemake.params  # noqa: F821
table = FrictionTable.model_validate(params.table)
spec = run_spec(OnedofJob.model_validate(params.onedof).onedof, table.scene, table.reading, table.method)
solver = switch_solver(SwitchSettings.model_validate(params.validation["solver"]), "validation.solver")
round_trip = RoundTrip.model_validate(params.validation["round_trip"])
cases = round_trip_cases(
    LawModel.from_belt_model(spec.model),
    TabulatedLaw.from_file(snakemake.input.table),  # noqa: F821
    spec.t_end,
    spec.t_eval,
    solver,
    round_trip.extension_factor,
    law_from_config(round_trip.curved_law.model_dump(), key="validation.round_trip.curved_law"),
    round_trip.bins,
    SwitchSolver(**round_trip.curved_solver.model_dump(exclude_none=True)),
)
main = cases["fig17_table"]
source_check = float(np.max(np.abs(main.x_source - read_dataset(snakemake.input.source).displacement.values)))  # noqa: F821
write_csv(round_trip_rows(cases), snakemake.output.csv)  # noqa: F821
write_dataset(
    round_trip_dataset(main, cases, source_check),
    snakemake.output.nc,  # noqa: F821
    scene=spec.scene_attrs(),
    interpretation={
        **spec.interpretation(),
        "round_trip": round_trip.model_dump(exclude_none=True),
        "table": snakemake.input.table,  # noqa: F821
    },
    method={"name": "switch", **solver.settings},
    title="Fig. 17 round trip: the 1-DOF model driven by its own friction table",
)
