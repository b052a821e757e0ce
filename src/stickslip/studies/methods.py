"""The methods study (work-precision and failure map of the integration methods against the exact solver):
config entries expanded to methods, one study run per scene, and the datasets the pipeline writes."""

from __future__ import annotations

import json
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from ..analysis.errors import measure_run, segment_cycle_metrics
from ..analysis.failure import FAILURE_KINDS, classify
from ..analysis.metrics import cf_variable
from ..model import BeltModel, BeltParams
from ..schema import MethodsStudy, StudyMethod, Timing, given
from ..solvers import make_solver

if TYPE_CHECKING:  # the config check expands the methods at parse time: xarray only where data is made
    import xarray as xr


def expand_methods(entries: Iterable[StudyMethod]) -> list[tuple[str, dict, str]]:
    """Method entries -> (solver name, settings, label), one per swept combination."""
    out = []
    for entry in entries:
        for settings in entry.combinations():
            shown = ",".join(f"{k}={v}" for k, v in settings.items())
            out.append((entry.solver, settings, entry.solver + (f"[{shown}]" if settings else "")))
    return out


INTERPRETATION = (
    "consistent friction law F = -mu_s N (sgn(v_r) - sigma v_r); paper numbers used as given (units as_given)"
)


def scene_model(study: MethodsStudy, scene: str, **overrides) -> BeltModel:
    sc = study.scenes[scene]
    params = BeltParams(**{**given(study.base_params), **given(sc.params), **overrides})
    return BeltModel.build(params, sc.variant)


def run_scene(study: MethodsStudy, model, t_end, methods, paper=True, timing: Timing | None = None):
    """Reference + every method; returns (records, reference, ref_cycle, paper_record). ``timing`` replaces
    the study's (the repeats of a timed run)."""
    n = int(round(t_end / study.output_dt)) + 1
    t_eval = np.linspace(0.0, t_end, n)
    exact = make_solver("exact")
    ref = exact.solve(model, t_end, t_eval)
    if not ref.ok:
        raise RuntimeError(f"exact reference failed: {ref.stats.message}")
    ref_cycle = segment_cycle_metrics(exact.segments(model, t_end))
    kw = {**study.budget.model_dump(), **(timing or study.timing).model_dump()}
    records = []
    for name, settings, label in methods:
        traj, rec = measure_run(make_solver(name, **settings), model, t_end, t_eval, ref, ref_cycle, **kw)
        rec.update(classify(traj, ref, model.params))
        rec.update(solver=name, settings=json.dumps(settings, sort_keys=True), label=label)
        records.append(rec)
    paper_rec = None
    if paper:
        solver, paper_settings = study.paper_method.solver, study.paper_method.settings or {}
        # The paper's method is usually one of the listed settings: a deterministic run, so not run twice
        # (in the decelerating scene it stalls: 2.6 s of CPU to the budget).
        paper_rec = next(
            (r for r, (name, s, _) in zip(records, methods) if name == solver and s == paper_settings),
            None,
        )
        if paper_rec is None:
            _, paper_rec = measure_run(
                make_solver(solver, **paper_settings), model, t_end, t_eval, ref, ref_cycle, **kw
            )
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
    import xarray as xr

    ds = xr.Dataset()
    for key, (units, long_name) in NUMERIC.items():
        ds[key] = cf_variable(dim, np.array([float(r[key]) for r in records]), units, long_name)
    for key in FLAGS:
        flags = np.array([int(bool(r[key])) for r in records], dtype=np.int8)
        ds[key] = cf_variable(dim, flags, "1", f"failure flag: {key}", flag_values="0 1")
    for key, long_name in STRINGS.items():
        ds[key] = (dim, np.array([str(r[key]) for r in records], dtype=object), {"long_name": long_name})
    return ds


def work_precision_dataset(study: MethodsStudy, scene: str) -> tuple[xr.Dataset, BeltModel]:
    """Every method of ``methods_study.methods`` on one scene, against the exact reference, with each run's
    CPU time relative to the paper's method on the same machine and run."""
    model = scene_model(study, scene)
    records, _, ref_cycle, paper = run_scene(study, model, study.t_end, expand_methods(study.methods))
    ds = records_dataset(records)
    ds["cpu_ratio_to_paper"] = cf_variable(
        "run",
        ds["cpu_time"].values / paper["cpu_time"],
        "1",
        "CPU time / paper's method (sign+RK45 rtol 1e-3), same run",
    )
    ds.attrs.update(
        title=f"Work-precision of integration methods, scene {scene}",
        paper_method_cpu_time=paper["cpu_time"],
        paper_method_rhs_evaluations=paper["rhs_evaluations"],
        reference_period=ref_cycle["period"],
        reference_amplitude=ref_cycle["amplitude"],
        t_end=study.t_end,
    )
    return ds, model


#: The failure map records which runs fail and how, not how fast they are: each run once (a third of the
#: map's CPU went to repeating its short runs for a timing no chart shows).
FAILURE_MAP_TIMING = Timing(min_repeats=1, max_repeats=1, min_total_cpu=0.0)


def failure_map_dataset(study: MethodsStudy) -> xr.Dataset:
    """``methods_study.failure_map``: every method's run and failure flags over one swept parameter."""
    import xarray as xr

    fm = study.failure_map
    methods = expand_methods(fm.methods)
    rows = []
    for value in fm.values:
        model = scene_model(study, fm.scene, **{fm.parameter: value})
        records, *_ = run_scene(study, model, fm.t_end, methods, paper=False, timing=FAILURE_MAP_TIMING)
        rows.append(records_dataset(records))
    ds = xr.concat(rows, dim="parameter")
    ds = ds.assign_coords(
        parameter=(
            "parameter",
            np.array(fm.values, dtype=float),
            {
                "long_name": f"swept parameter {fm.parameter}",
                "units": "s mm-1" if fm.parameter == "sigma" else "1",
            },
        ),
        run=("run", np.arange(len(methods))),
    )
    labels = np.array([m[2] for m in methods], dtype=object)
    ds["label"] = ("run", labels, {"long_name": "method and settings"})
    ds.attrs.update(
        title="Failure map of integration methods",
        swept_parameter=fm.parameter,
        t_end=fm.t_end,
        timing="each run once: cpu_time is a single measurement",
    )
    return ds
