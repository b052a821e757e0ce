"""Where methods fail: classification of a run against the exact reference.

Indicators (all numbers, stored as data):

``diverged``       the run produced non-finite states or left a box 10x the reference's range
``step_collapse``  the method stalled: work budget exhausted, or the integrator gave up on its step size
``missed_stick``   the exact solution sticks but the method spends < 10 % of that time near v_r = 0
``chatter``        v_r changes sign repeatedly while the exact solution sticks (the sign RHS flips)
``creep``          x - X_b(t) (X_b = integral of the belt speed) drifts while the exact solution sticks
                   (measured over the inner 80 % of the first reference stick, before any phase error
                   has built up, so a shifted orbit is not mistaken for creep; tolerance relative to
                   the reference's peak-to-peak x)

``failure_kind`` is the most severe of these (in the order above) or 'none'.
"""

from __future__ import annotations

import math

import numpy as np

FAILURE_KINDS = ("none", "diverged", "step_collapse", "missed_stick", "chatter", "creep")


def belt_position(params, t):
    """X_b(t) = integral of V_b from 0 [mm] (linear deceleration, then at rest)."""
    t = np.asarray(t, dtype=float)
    ts = min(params.belt_stop_time, 1e300)
    tc = np.minimum(t, ts)
    return params.belt_velocity * tc - 0.5 * params.belt_deceleration * tc * tc


def stick_intervals(ref_segments, min_length: float = 0.0):
    """(t0, t1) of the reference's stick segments longer than ``min_length``."""
    if ref_segments is None:
        return []
    return [
        (float(a), float(b))
        for a, b, ph in np.asarray(ref_segments).reshape(-1, 3)
        if ph == 0 and b - a > min_length
    ]


def classify(
    traj, ref, params, *, creep_tolerance: float = 1e-3, chatter_count: int = 2, band: float | None = None
) -> dict:
    """Failure indicators of ``traj`` against the exact ``ref`` (same samples, ``ref.segments`` set).

    creep_tolerance: allowed drift relative to the reference's peak-to-peak x.
    chatter_count: sign changes of v_r per reference stick interval above which the run chatters.
    band: |v_r| [mm/s] counted as 'near stick' for the missed-stick test (default 1 % of V_b(0)).
    """
    t = traj.t
    x, v = traj.x, traj.v
    vb = traj.belt_velocity
    band = band if band is not None else 0.01 * max(params.belt_velocity, 1e-12)
    scale = max(float(np.ptp(ref.x)), 1e-12)
    out = {
        "diverged": False,
        "step_collapse": False,
        "missed_stick": False,
        "chatter": False,
        "creep": False,
        "creep_mm": 0.0,
        "sign_changes_in_stick": 0.0,
        "stick_time_ratio": math.nan,
    }
    msg = (traj.stats.message or "").lower()
    finite = bool(np.all(np.isfinite(x)) and np.all(np.isfinite(v)))
    if traj.stats.status != "ok":
        if "budget" in msg or "step size" in msg or "max_steps" in msg:
            out["step_collapse"] = True
        else:
            out["diverged"] = True
    elif not finite or np.max(np.abs(x)) > 10 * (np.max(np.abs(ref.x)) + scale):
        out["diverged"] = True
    if not finite:
        out["diverged"] = out["diverged"] or not out["step_collapse"]
        out["failure_kind"] = _kind(out)
        return out

    intervals = stick_intervals(ref.segments, min_length=0.05)
    vr = v - vb
    if intervals:
        dt = np.gradient(t)
        in_ref_stick = np.zeros(t.shape, bool)
        for a, b in intervals:
            in_ref_stick |= (t >= a) & (t <= b)
        ref_stick_time = float(np.sum(dt[in_ref_stick]))
        near = np.abs(vr) <= band
        out["stick_time_ratio"] = float(np.sum(dt[near]) / ref_stick_time) if ref_stick_time else math.nan
        out["missed_stick"] = bool(out["stick_time_ratio"] < 0.1)
        xb = belt_position(params, t)
        rel = x - xb
        changes = []
        for a, b in intervals:
            m = _inner(t, a, b)
            if m.sum() < 3:
                continue
            s = np.sign(vr[m][np.abs(vr[m]) > 1e-12 * max(params.belt_velocity, 1e-12)])
            changes.append(int(np.sum(s[1:] != s[:-1])) if s.size > 1 else 0)
        if changes:
            out["sign_changes_in_stick"] = float(np.mean(changes))
            out["chatter"] = bool(out["sign_changes_in_stick"] > chatter_count)
        # creep on the first reference stick: every method starts from the same state, so no phase
        # error has built up yet and any drift of x - X_b is the method's own stick error
        m = _inner(t, *intervals[0])
        if m.sum() >= 2:
            drift = rel[m][-1] - rel[m][0]
            out["creep_mm"] = float(abs(drift))
            out["creep"] = bool(out["creep_mm"] > creep_tolerance * scale)
    out["failure_kind"] = _kind(out)
    return out


def _kind(flags: dict) -> str:
    return next((kind for kind in FAILURE_KINDS[1:] if flags.get(kind)), "none")


def _inner(t, a: float, b: float):
    """The samples in the inner 80 % of [a, b]."""
    pad = 0.1 * (b - a)
    return (t >= a + pad) & (t <= b - pad)
