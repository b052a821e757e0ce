"""1-DOF studies: a scene run (a paper figure's curve plus its limit-cycle metrics) and a parameter sweep,
each as a dataset."""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..analysis.critical import continuation, critical_speed
from ..analysis.divergence import BoundedSolver
from ..analysis.friction_curve import friction_along_solution, friction_table
from ..analysis.metrics import METRICS, cf_variable, extra_metrics, limit_cycle_metrics, metric_attrs
from ..analysis.outcome import FLAG_ATTRS, mechanism, outcome_name, run_outcome
from ..analysis.sweep import chunk_dataset, chunk_points, grid_size, merge_chunks, run_points
from ..io.netcdf import trajectory_dataset
from ..model.amplitude import amplitude_correct, amplitude_printed, correct_peak, printed_peak
from ..model.equations import BeltModel
from ..model.laws import LawModel
from ..model.params import effective_mass
from ..schema import OnedofRuns
from .specs import RunSpec, SweepSpec, baseline_spec, run_spec, sweep_spec


def scene_run_dataset(spec: RunSpec) -> xr.Dataset:
    """Solve one scene x reading x method; time series, metrics, and the solver's status and settings
    (``attrs['solver_run_settings']``) and its ``outcome`` with the mechanism behind it. Every metric is
    stored; one a run does not define (no stick to time, a run that diverged or failed) is NaN."""
    traj = BoundedSolver(_ReusedSolve(spec), spec.transient).solve(spec.model, spec.t_end, spec.t_eval)
    metrics = limit_cycle_metrics(traj, spec.transient, spec.count_window)
    ds = trajectory_dataset(traj, metrics)
    ds["slip_fraction"] = ((), 1.0 - float(ds.stick_fraction), metric_attrs("slip_fraction"))
    outcome = outcome_name(metrics["outcome"].value)
    velocity = float(ds.max_velocity) if "max_velocity" in ds else float("nan")
    why = mechanism(spec.model, outcome, velocity, traj.stats.message)  # the sentence behind the outcome
    ds["outcome"] = (
        (),
        np.int8(metrics["outcome"].value),
        {**metric_attrs("outcome"), **FLAG_ATTRS, "mechanism": why},
    )
    extra = dict.fromkeys(EXTRA_METRICS, float("nan"))
    if traj.ok:
        friction, normal = spec.friction, spec.params.normal_force
        extra = extra_metrics(traj.t, traj.x, traj.v, traj.belt_velocity, traj.phase, friction, normal)
    for name, value in extra.items():
        ds[name] = ((), value, metric_attrs(name))
    ds.attrs["solver_run_settings"] = dict(traj.settings)
    stats = traj.stats
    ds.attrs["solver_message"] = f"{stats.status}, {stats.steps} segments/steps: {stats.message}"
    # the run's status as scipy's solve_ivp states one: success (a cycle, rest or no stick: the model
    # answered), diverged (also the model's answer, the motion grows without bound) or failed (numerical:
    # nothing computed); success is 1 unless numerically failed
    status = outcome if outcome in ("diverged", "failed") else "success"
    ds.attrs.update(
        status=status, success=int(status != "failed"), message=f"{outcome.replace('_', ' ')}: {why}"
    )
    return ds


#: The last few solves, by everything a solve reads (the measurement window is not among it): the ensemble's
#: ``window`` member measures the base run over a later window, so it reuses the base run's trajectory
#: instead of integrating it again (tests/studies/test_onedof_studies.py shows the two are identical).
_SOLVES: dict[tuple, object] = {}
_SOLVES_KEPT = 8


class _ReusedSolve:
    """The spec's solver, answering a solve it has already done with a copy of that trajectory."""

    def __init__(self, spec: RunSpec):
        self.spec, self.inner = spec, spec.solver()
        self.name, self.settings = self.inner.name, self.inner.settings

    def solve(self, model, t_end, t_eval=None):
        import copy

        s = self.spec
        key = (
            repr(s.params),
            s.variant,
            repr(sorted(s.solver_settings.items())),
            repr(s.law),
            s.t_end,
            s.output_dt,
        )
        if key not in _SOLVES:
            if len(_SOLVES) >= _SOLVES_KEPT:
                _SOLVES.pop(next(iter(_SOLVES)))
            _SOLVES[key] = self.inner.solve(model, t_end, t_eval)
        return copy.deepcopy(_SOLVES[key])  # the caller may mark it diverged: the kept one stays as solved


#: Metrics beyond the limit-cycle table (analysis.metrics.extra_metrics), NaN where a run defines none.
EXTRA_METRICS = tuple(METRICS)[tuple(METRICS).index("early_amplitude") :]


SWEEP_METRICS = (
    "stick_fraction",
    "stick_time",
    "slip_time",
    "frequency_peaks",
    "amplitude_peak_to_peak",
    "amplitude_peak_to_zero",
)
#: Metrics also stored per paper value as scalars the claims table can name (e.g. frequency_peaks_at_0p9).
POINT_METRICS = (
    "frequency_peaks",
    "amplitude_peak_to_peak",
    "amplitude_peak_to_zero",
    "stick_time",
    "slip_time",
)


def point_mechanism(spec: SweepSpec, point: dict, traj) -> str:
    """The mechanism sentence of one sweep run (stickslip.analysis.outcome), from its own parameters."""
    params = spec.base.params.with_(**point)
    model = BeltModel.build(params, spec.base.variant) if spec.law is None else LawModel(params, spec.law)
    outcome = run_outcome(traj, spec.base.transient)
    window = np.asarray(traj.t) >= spec.base.transient
    velocity = float(np.max(traj.v[window])) if traj.ok and window.any() else float("nan")
    return mechanism(model, outcome, velocity, traj.stats.message)


def sweep_dataset(spec: SweepSpec, dense: bool, progress=None) -> xr.Dataset:
    """One parameter sweep (Figs. 10-14, belt speed) for one reading: metrics per point, and for the paper's
    values (``dense=False``) each run's time series. Every point is solved once. Failed or diverging runs
    keep NaN metrics and solver_ok = 0, with the reason in failure_message."""
    axis = spec.axis(dense)
    base = spec.base
    n = grid_size([axis])
    points = chunk_points([axis], n, 0)
    messages, mechanisms = [""] * n, [""] * n
    series = np.full((n, 2, base.t_eval.size), np.nan)

    def keep(i, traj):
        messages[i] = traj.stats.message or "none"
        mechanisms[i] = point_mechanism(spec, points[i], traj)
        if not dense and traj.ok:
            series[i] = traj.x, traj.v

    results = run_points(
        base.params,
        base.variant,
        points,
        BoundedSolver(base.solver(), base.transient),
        base.t_end,
        base.t_eval,
        base.transient,
        base.count_window,
        progress=progress,
        on_trajectory=keep,
        law=spec.law,
    )
    ds = merge_chunks([axis], [chunk_dataset([axis], n, 0, results)])
    for m in SWEEP_METRICS:  # every run failed: keep the variables, all NaN
        if m not in ds:
            ds[m] = (spec.parameter, np.full(n, np.nan), metric_attrs(m))
    ds["slip_fraction"] = (spec.parameter, 1.0 - ds.stick_fraction.values, metric_attrs("slip_fraction"))
    if not dense:  # the paper's curves: keep each run's time series
        ds = ds.assign_coords(time=cf_variable("time", base.t_eval, "s", "time"))
        dims = (spec.parameter, "time")
        ds["displacement"] = cf_variable(dims, series[:, 0], "mm", "mass displacement x")
        ds["velocity"] = cf_variable(dims, series[:, 1], "mm s-1", "mass velocity")
        at_values = {}  # assigned at once: each single assignment re-aligns the whole dataset
        for m in POINT_METRICS:
            for value in spec.values:
                at_values[f"{m}_at_{value:g}".replace(".", "p")] = (
                    (),
                    float(ds[m].sel({spec.parameter: value})),
                    {
                        **ds[m].attrs,
                        "long_name": f"{ds[m].attrs['long_name']} at {spec.parameter} = {value:g}",
                    },
                )
        ds = ds.assign(at_values)
    ds["failure_message"] = (
        spec.parameter,
        np.array(messages, dtype=object),
        {"long_name": "solver or divergence message of each run"},
    )
    ds["outcome_mechanism"] = (
        spec.parameter,
        np.array(mechanisms, dtype=object),
        {"long_name": "why each run ends in its outcome (closed form of its slip phase)"},
    )
    ds.attrs.update(
        {
            "sweep_parameter": spec.parameter,
            "sweep_figure": spec.figure,
            "sweep_kind": "dense" if dense else "paper values",
            "friction_law": repr(spec.law) if spec.law is not None else "the reading's",
            "failed_runs": int(np.sum(ds.solver_ok.values != 1)),
        }
    )
    return ds


def sweep_from_config(
    onedof: OnedofRuns, *, sweep: str, reading: str, dense: bool, progress=None
) -> xr.Dataset:
    """``sweep_dataset`` of ``onedof.sweeps.<sweep>`` for a reading. ``progress`` is a factory of a fresh
    ``progress(done, total)`` callback (one per call: an ensemble calls this once per member)."""
    return sweep_dataset(sweep_spec(onedof, sweep, reading), dense, progress() if progress else None)


CRITICAL_UNITS = {
    "stick_fraction": ("1", "fraction of steady-window samples in stick"),
    "stick_time": ("s", "mean stick duration"),
    "amplitude_peak_to_peak": ("mm", "peak-to-peak displacement"),
    "frequency_peaks": ("Hz", "frequency from peak spacing"),
    "solver_ok": ("1", "run finished and bounded (1)"),
    "steady_sliding_stable": ("1", "steady sliding linearly stable (1), neutral (0.5), unstable (0)"),
}


def critical_speed_dataset(spec: RunSpec, speeds: np.ndarray, t_end: float, transient: float) -> xr.Dataset:
    """Continuation over belt speed with the exact solver: metrics per speed and the critical speed (the
    smallest speed from which on no run sticks), with the first speed of linearly stable steady sliding."""
    solver = BoundedSolver(spec.solver(), transient)
    out, messages = continuation(spec.params, spec.variant, speeds, solver, t_end, transient, spec.output_dt)
    vc = critical_speed(speeds, out["stick_fraction"], out["solver_ok"])
    stable = out["steady_sliding_stable"]
    first_stable = float(speeds[np.argmax(stable == 1)]) if np.any(stable == 1) else float("inf")
    ds = xr.Dataset(
        {k: cf_variable("belt_velocity", out[k], u, n) for k, (u, n) in CRITICAL_UNITS.items()},
        coords={"belt_velocity": cf_variable("belt_velocity", speeds, "mm s-1", "belt speed V_b")},
    )
    ds["critical_belt_speed"] = cf_variable(
        (), vc, "mm s-1", "smallest V_b from which on no run sticks (0: never sticks; inf: none)"
    )
    ds["steady_sliding_stable_from"] = cf_variable(
        (),
        first_stable,
        "mm s-1",
        "smallest swept V_b at which steady sliding is linearly stable (inf: none)",
    )
    ds["has_critical_speed"] = cf_variable(
        (),
        float(0 < vc < np.inf),
        "1",
        "stick-slip present at low speed and gone above a finite speed (1) or not (0)",
    )
    ds.attrs["failures"] = "; ".join(messages) or "none"
    return ds


def critical_speed_from_config(onedof: OnedofRuns, *, reading: str) -> xr.Dataset:
    """``critical_speed_dataset`` of the baseline scene under ``onedof.critical_speed`` for a reading."""
    study = onedof.critical_speed
    speeds = np.geomspace(study.start, study.stop, study.num)
    return critical_speed_dataset(baseline_spec(onedof, reading), speeds, study.t_end, study.transient)


def friction_table_dataset(spec: RunSpec, bins: int) -> xr.Dataset:
    """Fig. 17: mu(|v_r|) along a run of ``spec`` - every slip sample and the binned table the FE scenes
    read (mu_static at rest, then bin means, ascending)."""
    run = scene_run_dataset(spec)
    speed, mu = friction_along_solution(
        run.velocity.values,
        run.belt_velocity.values,
        run.phase.values,
        spec.model.friction,
        spec.params.normal_force,
    )
    table_v, table_mu = friction_table(speed, mu, spec.params.mu_s, bins)
    max_speed = float(np.max(speed)) if len(speed) else np.nan
    return xr.Dataset(
        {
            "mu": cf_variable("relative_speed", table_mu, "1", "friction coefficient |F|/N"),
            "sample_relative_speed": cf_variable("sample", speed, "mm s-1", "|v_r| of each slip sample"),
            "sample_mu": cf_variable("sample", mu, "1", "|F|/N of each slip sample"),
            "max_relative_speed": cf_variable(
                (), max_speed, "mm s-1", "largest relative speed along the solution"
            ),
            "mu_at_max_relative_speed": cf_variable(
                (), float(table_mu[-1]), "1", "friction coefficient at the largest relative speed"
            ),
            "mu_static": cf_variable((), spec.params.mu_s, "1", "static friction coefficient"),
        },
        coords={"relative_speed": cf_variable("relative_speed", table_v, "mm s-1", "relative speed |v_r|")},
    )


def friction_table_from_config(onedof: OnedofRuns) -> xr.Dataset:
    """``friction_table_dataset`` of the run ``onedof.friction_table`` names (scene, reading, method)."""
    return friction_table_dataset(friction_table_spec(onedof), onedof.friction_table.bins)


def friction_table_spec(onedof: OnedofRuns) -> RunSpec:
    """The run ``onedof.friction_table`` names: the 1-DOF cycle the FE scenes' friction law comes from."""
    table = onedof.friction_table
    return run_spec(onedof, table.scene, table.reading, table.method)


def eq6_dataset(spec: RunSpec, f_max: float, points: int) -> xr.Dataset:
    """Fig. 4: Eq. 6 as printed and the dimensionally correct 1-DOF amplitude curve, peaks in closed form
    (F = mu_s N assumed for the paper's 'friction force')."""
    p = spec.params
    force = p.mu_s * p.normal_force
    f = np.linspace(0.0, f_max, points)
    w = 2 * np.pi * f
    fp, ap = printed_peak(force, p.stiffness, p.damping)
    fc, ac = correct_peak(force, p.stiffness, p.damping, p.mass)
    fs, as_ = correct_peak(force, p.stiffness, p.damping, effective_mass(p.mass, "si"))

    def scalar(value, units, long_name):
        return cf_variable((), float(value), units, long_name)

    return xr.Dataset(
        {
            "amplitude_printed": cf_variable(
                "frequency",
                amplitude_printed(w, force, p.stiffness, p.damping),
                "mm",
                "Eq. 6 as printed: F/sqrt((K-w^2)^2 + c w^2)",
            ),
            "amplitude_correct": cf_variable(
                "frequency",
                amplitude_correct(w, force, p.stiffness, p.damping, p.mass),
                "mm",
                "1-DOF: F/sqrt((K-M w^2)^2 + (C w)^2)",
            ),
            "peak_frequency_printed": scalar(fp, "Hz", "peak of Eq. 6 as printed (w^2 = K - c/2)"),
            "peak_amplitude_printed": scalar(ap, "mm", "peak amplitude of Eq. 6 as printed"),
            "peak_frequency_correct": scalar(fc, "Hz", "resonance of the 1-DOF curve (w^2 = K/M - C^2/2M^2)"),
            "peak_amplitude_correct": scalar(ac, "mm", "peak amplitude of the 1-DOF curve"),
            "peak_frequency_correct_si": scalar(
                fs, "Hz", "resonance with M converted to N s^2/mm (0: overdamped, no peak)"
            ),
            "peak_amplitude_correct_si": scalar(as_, "mm", "peak amplitude with M converted to N s^2/mm"),
            "force": scalar(force, "N", "F = mu_s N assumed for 'the friction force' of Eq. 6"),
        },
        coords={"frequency": cf_variable("frequency", f, "Hz", "excitation frequency w / 2 pi")},
    )


def eq6_from_config(onedof: OnedofRuns) -> xr.Dataset:
    """``eq6_dataset`` of the baseline scene with ``onedof.eq6`` (f_max, points)."""
    return eq6_dataset(baseline_spec(onedof), onedof.eq6.f_max, onedof.eq6.points)
