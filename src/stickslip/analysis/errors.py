"""Error of a trajectory against the exact reference: state over the whole run, limit-cycle period and
amplitude.

Limit-cycle metrics are read from samples with cubic Hermite interpolation between samples (x and v are
both known), so the extrema of x are located to O(dt^4); for the exact solver they are also available
to machine precision from the closed-form segments (:func:`segment_cycle_metrics`).
"""

from __future__ import annotations

import math

import numpy as np


def state_error(traj, ref) -> dict:
    """Max-norm error over the whole run, relative to the reference's peak-to-peak x and v.

    ``state`` = max over samples of max(|dx|/ptp(x_ref), |dv|/ptp(v_ref)); inf if the run has NaNs.
    """
    if traj.t.shape != ref.t.shape or not np.allclose(traj.t, ref.t, rtol=0, atol=1e-12):
        raise ValueError("state_error: trajectory and reference must share the sample times")
    xs = max(float(np.ptp(ref.x)), 1e-300)
    vs = max(float(np.ptp(ref.v)), 1e-300)
    dx = np.abs(traj.x - ref.x)
    dv = np.abs(traj.v - ref.v)
    if not (np.all(np.isfinite(dx)) and np.all(np.isfinite(dv))):
        return {"state": math.inf, "state_rms": math.inf, "x_max": math.inf, "v_max": math.inf}
    e = np.maximum(dx / xs, dv / vs)
    return {
        "state": float(e.max()),
        "state_rms": float(np.sqrt(np.mean(e * e))),
        "x_max": float(dx.max()),
        "v_max": float(dv.max()),
    }


def _hermite_extremum(t0, t1, x0, x1, v0, v1):
    """Extremum (t, x) of the cubic Hermite interpolant on [t0, t1] where v changes sign."""
    from scipy.optimize import brentq  # here: the parse-time config check imports this module

    h = t1 - t0
    # x(s) = x0 + h v0 s + (3dx - h(2v0+v1)) s^2 + (h(v0+v1) - 2dx) s^3,  s in [0, 1]
    dx = x1 - x0
    c1, c2, c3 = h * v0, 3 * dx - h * (2 * v0 + v1), h * (v0 + v1) - 2 * dx

    # derivative c1 + 2 c2 s + 3 c3 s^2 = 0; pick the root in [0, 1] (bisection-safe via brentq)
    def d(s):
        return c1 + 2 * c2 * s + 3 * c3 * s * s

    if d(0.0) == 0.0:
        s = 0.0
    elif d(1.0) == 0.0:
        s = 1.0
    elif d(0.0) * d(1.0) < 0:
        s = brentq(d, 0.0, 1.0, xtol=1e-15)
    else:
        s = 0.0 if abs(d(0.0)) < abs(d(1.0)) else 1.0
    return t0 + h * s, x0 + s * (c1 + s * (c2 + s * c3))


def sampled_extrema(t, x, v):
    """(t_max, x_max, t_min, x_min) arrays: maxima where v goes + to -, minima where v goes - to +."""
    t, x, v = (np.asarray(a, dtype=float) for a in (t, x, v))
    out = {"max": ([], []), "min": ([], [])}
    sv = np.sign(v)
    for i in range(len(t) - 1):
        if sv[i] > 0 and sv[i + 1] <= 0 or sv[i] < 0 and sv[i + 1] >= 0:
            if sv[i + 1] == 0 and i + 2 < len(t) and np.sign(v[i + 2]) == sv[i]:
                continue  # touches zero without changing sign
            kind = "max" if sv[i] > 0 else "min"
            te, xe = _hermite_extremum(t[i], t[i + 1], x[i], x[i + 1], v[i], v[i + 1])
            out[kind][0].append(te)
            out[kind][1].append(xe)
    return tuple(np.array(a) for a in (*out["max"], *out["min"]))


def cycle_metrics(t, x, v, cycles: int = 3) -> dict:
    """Period (spacing of successive maxima of x) and peak-to-peak amplitude over the last ``cycles``."""
    tmax, xmax, _, xmin = sampled_extrema(t, x, v)
    if not np.all(np.isfinite(x)):
        return {"period": math.nan, "amplitude": math.nan}
    return _last_cycles(tmax, xmax, xmin, cycles)


def _last_cycles(tmax, xmax, xmin, cycles: int) -> dict:
    """Period (mean spacing of the maxima) and peak-to-peak amplitude over the last ``cycles``; NaN with
    fewer than two maxima or no minimum."""
    if len(tmax) < 2 or len(xmin) < 1:
        return {"period": math.nan, "amplitude": math.nan}
    n = min(cycles, len(tmax) - 1)
    period = float(np.mean(np.diff(tmax[-(n + 1) :])))
    amplitude = float(np.mean(xmax[-n:]) - np.mean(xmin[-n:]))
    return {"period": period, "amplitude": amplitude}


def segment_cycle_metrics(segments, cycles: int = 3) -> dict:
    """Period and peak-to-peak amplitude from the exact solver's closed-form segments (machine precision).

    Extrema of x are the zeros of v inside slip segments, refined with Brent's method on the closed form.
    """
    from scipy.optimize import brentq  # here: the parse-time config check imports this module

    tmax, xmax, tmin, xmin = [], [], [], []
    for seg in segments:
        if seg.phase == 0 or seg.t1 - seg.t0 <= 0:
            continue
        grid = np.linspace(seg.t0, seg.t1, 257)
        _, vg = seg.state(grid)
        for i in range(len(grid) - 1):
            if vg[i] == 0.0 or vg[i] * vg[i + 1] < 0:
                tz = (
                    grid[i]
                    if vg[i] == 0.0
                    else brentq(
                        lambda s, seg=seg: float(seg.state(s)[1]),
                        grid[i],
                        grid[i + 1],
                        xtol=1e-15,
                        rtol=4 * np.finfo(float).eps,
                    )
                )
                xz = float(seg.state(tz)[0])
                going_down = (vg[i] > 0) if vg[i] != 0 else (vg[i + 1] < 0)
                (tmax if going_down else tmin).append(tz)
                (xmax if going_down else xmin).append(xz)
    return _last_cycles(tmax, xmax, xmin, cycles)


def relative_error(value: float, reference: float) -> float:
    if not (math.isfinite(value) and math.isfinite(reference)):
        return math.inf if math.isfinite(reference) else math.nan
    return abs(value - reference) / max(abs(reference), 1e-300)


def compare(traj, ref, ref_cycle: dict | None = None) -> dict:
    """All error measures of ``traj`` against ``ref`` (same sample times)."""
    out = state_error(traj, ref)
    ref_cycle = ref_cycle if ref_cycle is not None else cycle_metrics(ref.t, ref.x, ref.v)
    cyc = cycle_metrics(traj.t, traj.x, traj.v)
    out.update(cyc)
    out["period_error"] = relative_error(cyc["period"], ref_cycle["period"])
    out["amplitude_error"] = relative_error(cyc["amplitude"], ref_cycle["amplitude"])
    return out


def measure_run(
    solver,
    model,
    t_end: float,
    t_eval,
    ref,
    ref_cycle: dict,
    *,
    max_rhs: int = 2_000_000,
    max_cpu: float = 20.0,
    min_repeats: int = 3,
    max_repeats: int = 25,
    min_total_cpu: float = 0.3,
    slow_run: float = 1.0,
):
    """Run ``solver`` under a work budget, time it, and measure its error against ``ref``.

    CPU time is the minimum of repeated runs (process time): repeated until ``min_total_cpu`` seconds
    and ``min_repeats`` runs are done (at most ``max_repeats``); a run slower than ``slow_run`` s, or one
    that failed, is not repeated. Returns (trajectory, record) with record = errors + timing + counters.
    """
    from ..solvers.budget import run_with_budget

    times = []
    traj = None
    while True:
        traj = run_with_budget(solver, model, t_end, t_eval, max_rhs=max_rhs, max_cpu=max_cpu)
        times.append(traj.stats.cpu_time)
        if not traj.ok or traj.stats.cpu_time > slow_run:
            break
        if len(times) >= max_repeats or (len(times) >= min_repeats and sum(times) >= min_total_cpu):
            break
    record = compare(traj, ref, ref_cycle)
    record.update(
        {
            "cpu_time": float(min(times)),
            "cpu_time_median": float(np.median(times)),
            "repeats": len(times),
            "rhs_evaluations": int(traj.stats.rhs_evaluations),
            "steps": int(traj.stats.steps),
            "status": traj.stats.status,
            "message": traj.stats.message,
        }
    )
    return traj, record
