"""Thin wiring: work-precision of the single-equation methods on nonlinear laws (reference: switch solver)."""

import numpy as np

from stickslip.io.netcdf import write_dataset
from stickslip.validation.datasets import methods_dataset
from stickslip.validation.methods import methods_study
from stickslip.validation.setup import ValidationSetup

setup = ValidationSetup(snakemake.params.validation)
cfg = setup.cfg["methods_per_law"]
t_end = float(cfg["t_end"])
t_eval = np.linspace(0.0, t_end, int(round(t_end / cfg["output_dt"])) + 1)
for law, path in zip(cfg["laws"], snakemake.output, strict=True):
    records, ref_cycle = methods_study(
        setup.model(law), cfg["methods"], t_end, t_eval, setup.solver(), cfg["timing"]
    )
    ds = methods_dataset(records, ref_cycle)
    ds.attrs["paper_method"] = cfg["paper_method"]
    write_dataset(
        ds,
        path,
        scene={"law": setup.cfg["laws"][law], "base_params": setup.cfg["base_params"], "t_end": t_end},
        interpretation="one sign equation M x'' + C x' + K x = -N mu(|v_r|) sgn(v_r); reference: switch",
        method={"reference": setup.solver().settings, "timing": cfg["timing"]},
        title=f"Methods study on the {law} law: error vs CPU against the switch-model solver",
    )
