"""Thin wiring: the 1-DOF model driven by the Fig. 17 table vs the cycle the table came from."""

import numpy as np

from stickslip.io.netcdf import read_dataset, write_dataset
from stickslip.model.laws import LawModel, TabulatedLaw, law_from_config
from stickslip.schema import SwitchSettings
from stickslip.solvers.switch import SwitchSolver
from stickslip.studies.specs import run_spec
from stickslip.validation.compare import round_trip_cases
from stickslip.validation.datasets import round_trip_dataset, round_trip_rows, write_csv
from stickslip.validation.setup import switch_solver

src = snakemake.params.table
spec = run_spec(snakemake.params.onedof, src["scene"], src["reading"], src["method"])
validation = snakemake.params.validation
solver = switch_solver(SwitchSettings.model_validate(validation["solver"]), "validation.solver")
cfg = validation["round_trip"]
cases = round_trip_cases(
    LawModel.from_belt_model(spec.model),
    TabulatedLaw.from_file(snakemake.input.table),
    spec.t_end,
    spec.t_eval,
    solver,
    cfg["extension_factor"],
    law_from_config(cfg["curved_law"], key="validation.round_trip.curved_law"),
    cfg["bins"],
    SwitchSolver(**cfg["curved_solver"]),
)
main = cases["fig17_table"]
source_check = float(np.max(np.abs(main.x_source - read_dataset(snakemake.input.source).displacement.values)))
write_csv(round_trip_rows(cases), snakemake.output.csv)
write_dataset(
    round_trip_dataset(main, cases, source_check),
    snakemake.output.nc,
    scene=spec.scene_attrs(),
    interpretation={**spec.interpretation(), "round_trip": cfg, "table": snakemake.input.table},
    method={"name": "switch", **solver.settings},
    title="Fig. 17 round trip: the 1-DOF model driven by its own friction table",
)
