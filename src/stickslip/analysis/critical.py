"""Critical belt speed: natural-parameter continuation over V_b with the exact solver.

Each run starts from the previous run's final state (same displacement, same relative velocity), so a
stick-slip orbit is followed while it exists; a failed run restarts the next one from the paper's initial
condition (x0, v0 = V_b). The critical speed is the smallest swept V_b from which on no run sticks any more
(stick fraction 0 in the steady window for it and every faster run). Independent of the runs, steady sliding
(v = 0, v_r = -V_b) is linearly stable when the slip damping at |v_r| = V_b is positive: C - b below a
friction plateau, C beyond it (``steady_sliding_stable``).
"""

from __future__ import annotations

import numpy as np

from ..model.equations import BeltModel
from ..model.params import BeltParams
from ..solvers.base import sample_times
from .metrics import limit_cycle_metrics

KEYS = ("stick_fraction", "stick_time", "amplitude_peak_to_peak", "frequency_peaks")


def steady_sliding_stable(model: BeltModel, belt_speed: float) -> float:
    """1 if steady sliding at V_b is linearly stable, 0 if unstable, 0.5 if neutral (zero slip damping)."""
    f = model.friction
    c = model.params.damping - (0.0 if belt_speed > f.plateau_speed else f.b)
    return 1.0 if c > 0 else (0.5 if c == 0 else 0.0)


def continuation(base: BeltParams, variant: str, speeds, solver, t_end: float, transient: float, dt: float):
    speeds = np.asarray(speeds, dtype=float)
    out = {k: np.full(len(speeds), np.nan) for k in KEYS + ("solver_ok", "steady_sliding_stable")}
    messages = []
    x, vr = base.x0, None
    t_eval = sample_times(t_end, dt)
    for i, vb in enumerate(speeds):
        params = base.with_(belt_velocity=float(vb), x0=float(x), v0=float(vb if vr is None else vb + vr))
        model = BeltModel.build(params, variant)
        out["steady_sliding_stable"][i] = steady_sliding_stable(model, vb)
        traj = solver.solve(model, t_end, t_eval)
        if not traj.ok:
            out["solver_ok"][i] = 0.0
            messages.append(f"V_b={vb:.4g}: {traj.stats.message}")
            x, vr = base.x0, None
            continue
        metrics = limit_cycle_metrics(traj, transient)
        out["solver_ok"][i] = 1.0
        for k in KEYS:
            out[k][i] = metrics[k].value if k in metrics else np.nan
        x, vr = float(traj.x[-1]), float(traj.v[-1] - traj.belt_velocity[-1])
    return out, messages


def critical_speed(speeds, stick_fraction, ok) -> float:
    """Smallest speed from which on every successful run has zero stick fraction; 0 if none ever sticks,
    inf if the fastest successful run still sticks (no critical speed in the swept range), NaN if
    runs faster than the last sticking one failed (undetermined)."""
    speeds, sf, ok = (np.asarray(a, dtype=float) for a in (speeds, stick_fraction, ok))
    good = ok == 1
    if not good.any():
        return float("nan")
    sticks = good & (sf > 0)
    if not sticks.any():
        return 0.0
    last = int(np.nonzero(sticks)[0][-1])
    if np.any((ok != 1) & (np.arange(len(speeds)) > last)):
        return float("nan")  # faster runs failed or diverged: whether stick-slip ends is undetermined
    after = np.nonzero(good & (np.arange(len(speeds)) > last))[0]
    return float(speeds[after[0]]) if after.size else float("inf")
