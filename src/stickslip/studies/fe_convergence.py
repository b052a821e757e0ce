"""Convergence of the beam-on-disc model in element count and time step (``fe.convergence``), with the beam's
modal errors against the closed-form cantilever."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe.beam import cantilever_errors
from ..fe.params import FrictionTable, SolverParams
from ..fe.quantities import INTERPRETATION, RESPONSE_QUANTITIES, cf_attrs, metric_attrs
from ..schema.fe import Convergence, FeJob
from .fe_config import as_mapping, deep_merge
from .fe_scene import run_scene


def max_deviation(q: str, values: np.ndarray) -> tuple[float, str]:
    """The largest deviation of ``q`` on the two finest meshes (every step) from the finest run: absolute
    for a fraction, relative otherwise."""
    ref = values[-1, -1]
    sub = values[-2:, :]
    if q.endswith("_fraction"):
        return float(np.abs(sub - ref).max()), "largest absolute deviation"
    dev = float(np.abs(sub / ref - 1).max()) if ref != 0 else float("nan")
    return dev, "largest relative deviation"


def _grid_runs(cv: Convergence, base: Mapping, n_el: list, sfs: list, friction: FrictionTable):
    """Every (n_elements, safety_factor) run: the quantities and time steps on the grid, and the modal
    errors per mesh."""
    vals = {q: np.zeros((len(n_el), len(sfs))) for q in RESPONSE_QUANTITIES}
    dt = np.zeros((len(n_el), len(sfs)))
    bend_err, ax_err = [], []
    for i, n in enumerate(n_el):
        for j, sf in enumerate(sfs):
            mp = deep_merge(
                base, {"beam": {"n_elements": n}, "solver": {"t_end": cv.t_end, "safety_factor": sf}}
            )
            r, m, scene = run_scene(mp, friction)
            for q in RESPONSE_QUANTITIES:
                vals[q][i, j] = m[q]
            dt[i, j] = r.dt
        bending, axial = cantilever_errors(scene.params.beam)
        bend_err.append(bending)
        ax_err.append(axial)
    return vals, dt, bend_err, ax_err


def _grid_coords(n_el: list, sfs: list) -> dict:
    return {
        "n_elements": cf_variable("n_elements", np.array(n_el), "1", "number of beam elements"),
        "safety_factor": cf_variable(
            "safety_factor", np.array(sfs, float), "1", "time step over the stable limit"
        ),
        "bending_mode": cf_variable("bending_mode", np.arange(1, 4), "1", "cantilever bending mode"),
    }


def convergence_dataset(job: FeJob, friction: FrictionTable) -> xr.Dataset:
    """Element count x time-step (safety factor) study of the base scene, plus the modal errors of the beam
    against the closed-form cantilever. For each quantity, the largest relative deviation from the finest
    run (most elements, smallest step) over the runs with at least the second-finest mesh is a scalar
    ``<quantity>_max_deviation`` (fractions: absolute deviation)."""
    cv = job.convergence
    base = as_mapping(job.scenes[cv.base])
    n_el = list(cv.n_elements)
    sfs = list(cv.safety_factors or [SolverParams.from_mapping(base.get("solver", {})).safety_factor])
    vals, dt, bend_err, ax_err = _grid_runs(cv, base, n_el, sfs, friction)
    dims = ("n_elements", "safety_factor")
    ds = xr.Dataset(coords=_grid_coords(n_el, sfs))
    for q in RESPONSE_QUANTITIES:
        ds[q] = (dims, vals[q], metric_attrs(q))
        dev, what = max_deviation(q, vals[q])
        ds[f"{q}_max_deviation"] = cf_variable(
            (), dev, "1", f"{what} of {q} on the two finest meshes from the finest run"
        )
    ds["time_step"] = cf_variable(dims, dt, "s", "time step used")
    ds["bending_frequency_error"] = cf_variable(
        ("n_elements", "bending_mode"),
        np.array(bend_err),
        "1",
        "relative error of the cantilever bending frequencies",
    )
    ds["axial_frequency_error"] = cf_variable(
        "n_elements", np.array(ax_err), "1", "relative error of the first axial frequency"
    )
    ds.attrs.update(
        cf_attrs(
            "Beam-on-disc convergence in element count and time step",
            model_interpretation=INTERPRETATION,
            base_scene=cv.base,
            method="explicit central difference per (n_elements, safety_factor); modal errors vs closed form",
        )
    )
    return ds
