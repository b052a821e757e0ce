"""Shared helpers of the methods-study scripts: config expansion, one study run, dataset writing."""

from __future__ import annotations

import json
import os

import numpy as np
import xarray as xr

from stickslip.analysis.errors import measure_run, segment_cycle_metrics
from stickslip.analysis.failure import FAILURE_KINDS, classify
from stickslip.model import BeltModel, BeltParams
from stickslip.solvers import make_solver
from stickslip.studies.methods import expand_methods  # noqa: F401 (re-exported to the scripts)

INTERPRETATION = (
    "consistent friction law F = -mu_s N (sgn(v_r) - sigma v_r); paper numbers used as given (units as_given)"
)


def scene_model(cfg, scene: str, **overrides) -> BeltModel:
    sc = cfg["scenes"][scene]
    params = BeltParams.from_mapping({**cfg["base_params"], **sc.get("params", {}), **overrides})
    return BeltModel.build(params, sc["variant"])


def run_scene(cfg, model, t_end, methods, paper=True):
    """Reference + every method; returns (records, reference, ref_cycle, paper_record)."""
    n = int(round(t_end * cfg["samples_per_second"])) + 1
    t_eval = np.linspace(0.0, t_end, n)
    exact = make_solver("exact")
    ref = exact.solve(model, t_end, t_eval)
    if not ref.ok:
        raise RuntimeError(f"exact reference failed: {ref.stats.message}")
    ref_cycle = segment_cycle_metrics(exact.segments(model, t_end))
    kw = dict(cfg["budget"], **cfg["timing"])
    paper_rec = None
    if paper:
        pm = cfg["paper_method"]
        _, paper_rec = measure_run(
            make_solver(pm["solver"], **pm.get("settings", {})), model, t_end, t_eval, ref, ref_cycle, **kw
        )
    records = []
    for name, settings, label in methods:
        traj, rec = measure_run(make_solver(name, **settings), model, t_end, t_eval, ref, ref_cycle, **kw)
        rec.update(classify(traj, ref, model.params))
        rec.update(solver=name, settings=json.dumps(settings, sort_keys=True), label=label)
        records.append(rec)
    return records, ref, ref_cycle, paper_rec


NUMERIC = {
    "state": ("1", "max-norm state error relative to the reference's peak-to-peak x and v"),
    "state_rms": ("1", "rms state error relative to the reference's peak-to-peak x and v"),
    "x_max": ("mm", "max displacement error"),
    "v_max": ("mm s-1", "max velocity error"),
    "period": ("s", "limit-cycle period (spacing of maxima of x)"),
    "amplitude": ("mm", "limit-cycle peak-to-peak displacement"),
    "period_error": ("1", "relative period error vs exact"),
    "amplitude_error": ("1", "relative peak-to-peak amplitude error vs exact"),
    "cpu_time": ("s", "CPU time, min over repeats"),
    "cpu_time_median": ("s", "CPU time, median over repeats"),
    "repeats": ("1", "number of timed repeats"),
    "rhs_evaluations": ("1", "right-hand-side (force) evaluations"),
    "steps": ("1", "accepted steps (segments for the exact solver)"),
    "creep_mm": ("mm", "drift of x - X_b over the first reference stick"),
    "sign_changes_in_stick": ("1", "mean sign changes of v_r per reference stick interval"),
    "stick_time_ratio": ("1", "time with |v_r| <= 1% V_b over the reference stick time"),
}
FLAGS = ("diverged", "step_collapse", "missed_stick", "chatter", "creep")
STRINGS = {
    "solver": "method name",
    "settings": "method settings (JSON)",
    "label": "method and settings",
    "status": "run status: ok | failed (failed runs are data, not results)",
    "message": "failure message",
    "failure_kind": f"most severe failure, one of {FAILURE_KINDS}",
}


def records_dataset(records, dim="run") -> xr.Dataset:
    ds = xr.Dataset()
    for key, (units, long_name) in NUMERIC.items():
        ds[key] = (dim, np.array([float(r[key]) for r in records]), {"units": units, "long_name": long_name})
    for key in FLAGS:
        ds[key] = (
            dim,
            np.array([int(bool(r[key])) for r in records], dtype=np.int8),
            {"units": "1", "long_name": f"failure flag: {key}", "flag_values": "0 1"},
        )
    for key, long_name in STRINGS.items():
        ds[key] = (dim, np.array([str(r[key]) for r in records], dtype=object), {"long_name": long_name})
    return ds


def write(ds: xr.Dataset, path: str, *, scene: dict, method: dict) -> None:
    try:
        from stickslip.io.netcdf import write_dataset
    except ImportError:
        write_dataset = None
    if write_dataset is not None:
        write_dataset(ds, path, scene=scene, interpretation=INTERPRETATION, method=method)
        return
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "interpretation": INTERPRETATION,
            "scene": json.dumps(scene, sort_keys=True, default=str),
            "method": json.dumps(method, sort_keys=True, default=str),
        }
    )
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    tmp = path + ".tmp"
    ds.to_netcdf(tmp)
    os.replace(tmp, path)
