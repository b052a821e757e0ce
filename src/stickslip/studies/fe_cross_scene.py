"""Ratios of one scalar metric between two beam-on-disc scenes (``fe.cross_scene``), member by member of
their perturbation ensembles."""

from __future__ import annotations

import json
from collections.abc import Mapping

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe.quantities import INTERPRETATION, cf_attrs


def _step_value(ds: xr.Dataset, var: str, step: str) -> float:
    """A metric's value at one step of the step-halving check: the kept step value where it was withheld,
    else the value itself (it did not move)."""
    name = f"{var}_{step}"
    return float(ds[name]) if name in ds else float(ds[var])


def cross_scene_dataset(datasets: Mapping[str, xr.Dataset], pairs: Mapping[str, list]) -> xr.Dataset:
    """Ratios lhs/rhs of a metric between two scenes: pairs = {name: [lhs_scene, rhs_scene, variable]}."""
    ds = xr.Dataset()
    for name, (a, b, var) in pairs.items():
        va, vb = float(datasets[a][var]), float(datasets[b][var])
        ds[name] = cf_variable((), va / vb if vb != 0 else np.nan, "1", f"{var} of {a} over {b}")
        ea, eb = datasets[a].get(f"{var}_ensemble"), datasets[b].get(f"{var}_ensemble")
        if ea is not None and eb is not None and ea.shape == eb.shape:  # member by member
            with np.errstate(divide="ignore", invalid="ignore"):
                ratio = np.where(eb.values != 0, ea.values / eb.values, np.nan)
            ds[f"{name}_ensemble"] = cf_variable(
                ea.dims, ratio, "1", f"{var} of {a} over {b}, per perturbation-ensemble member"
            )
        if not np.isfinite(ds[name].values):  # an operand withheld by step halving: keep both steps' ratios
            for step in ("full_step", "half_step"):
                sa = _step_value(datasets[a], var, step)
                sb = _step_value(datasets[b], var, step)
                at = "dt" if step == "full_step" else "dt/2"
                ds[f"{name}_{step}"] = cf_variable(
                    (), sa / sb if sb != 0 else np.nan, "1", f"{var} of {a} over {b} at {at}"
                )
    ds.attrs.update(
        cf_attrs(
            "Beam-on-disc cross-scene ratios",
            model_interpretation=INTERPRETATION,
            method="ratios of scalar metrics",
            pairs=json.dumps(dict(pairs)),
        )
    )
    return ds
