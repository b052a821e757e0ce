"""Limit-cycle quantities from a run's switching record (period, stick onset and release, extrema), and the
textbook Coulomb cycle's in closed form.

Every solver's run is reduced to the same *event record* (stick onsets, releases, displacement extrema, each
located by the program that produced it), so the comparison does not depend on output sampling.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model.params import ParameterError, Positive, checked_arguments
from ..solvers.base import STICK

#: The quantities compared, with units and long names (netCDF/CSV columns).
QUANTITIES = {
    "period": ("s", "time between the last two stick onsets"),
    "stick_onset": ("s", "time of the last stick onset"),
    "stick_duration": ("s", "duration of the stick that starts one period before the last onset"),
    "onset_position": ("mm", "displacement at the last stick onset"),
    "release_position": ("mm", "displacement at the release in the last cycle"),
    "x_max": ("mm", "largest displacement in the last cycle"),
    "x_min": ("mm", "smallest displacement in the last cycle"),
}


@dataclass(frozen=True)
class EventRecord:
    """Times/positions of stick onsets and releases, and (t, x) of every displacement extremum."""

    onsets: np.ndarray  # (n, 2): t, x
    releases: np.ndarray  # (n, 2): t, x
    extrema: np.ndarray  # (n, 2): t, x at v = 0 during slip


def _velocity_of(seg):
    return lambda t: float(seg.state(t)[1])


def record_from_segments(segments, samples: int = 64) -> EventRecord:
    """Event record of a piecewise solution (exact or switch solver ``segments``).

    Extrema are the roots of v = 0 inside slip phases, bracketed on ``samples`` points and refined with
    Brent's method on the phase's own (closed-form or dense) solution.
    """
    from scipy.optimize import brentq  # here: the parse-time config check imports this module

    onsets, releases, extrema = [], [], []
    for k, seg in enumerate(segments):
        if seg.phase == STICK:
            if k > 0 and segments[k - 1].phase != STICK:
                onsets.append((seg.t0, float(seg.state(seg.t0)[0])))
            if k + 1 < len(segments) and segments[k + 1].phase != STICK:
                releases.append((seg.t1, float(seg.state(seg.t1)[0])))
            continue
        if seg.t1 <= seg.t0:
            continue
        tt = np.linspace(seg.t0, seg.t1, samples + 1)
        v = seg.state(tt)[1]
        velocity = _velocity_of(seg)
        for i in np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0]:
            tr = brentq(velocity, tt[i], tt[i + 1], xtol=1e-15, rtol=4 * np.finfo(float).eps)
            extrema.append((tr, float(seg.state(tr)[0])))
    return EventRecord(*(np.array(a, dtype=float).reshape(-1, 2) for a in (onsets, releases, extrema)))


def cycle_quantities(record: EventRecord) -> dict[str, float]:
    """The last complete cycle: from the second-last stick onset to the last one (NaN without two onsets)."""
    nan = float("nan")
    out = dict.fromkeys(QUANTITIES, nan)
    on = record.onsets
    if len(on) < 2:
        return out
    t_a, t_b = on[-2, 0], on[-1, 0]
    out["period"] = t_b - t_a
    out["stick_onset"] = t_b
    out["onset_position"] = on[-1, 1]
    rel = record.releases[(record.releases[:, 0] >= t_a) & (record.releases[:, 0] < t_b)]
    if len(rel):
        out["stick_duration"] = rel[0, 0] - t_a
        out["release_position"] = rel[0, 1]
    ext = record.extrema[(record.extrema[:, 0] > t_a) & (record.extrema[:, 0] < t_b)]
    # stick moves x monotonically: its ends (onset, release) are candidates too
    xs = np.concatenate((ext[:, 1], [on[-2, 1], on[-1, 1]], rel[:, 1] if len(rel) else []))
    out["x_max"], out["x_min"] = float(np.max(xs)), float(np.min(xs))
    return out


@checked_arguments(belt_velocity=Positive)
def coulomb_cycle(
    mass: float, stiffness: float, normal_force: float, belt_velocity: float, mu_s: float, mu_k: float
) -> dict:
    """The textbook stick-slip cycle of an undamped mass on a belt with Coulomb friction: period, stick/slip
    durations, release and onset positions, extrema.

    M x'' + K x = F, belt speed V_b > 0, friction mu_s N at rest and mu_k N in slip (mu_s > mu_k). Stick ends
    where the spring force reaches the static limit, x_s = mu_s N / K. The slip that follows (v < V_b,
    friction +mu_k N) is harmonic about x_k = mu_k N / K, starting at x_s - x_k = Delta = (mu_s - mu_k) N / K
    with v = V_b:

        x - x_k = A cos(w tau + phi),   A = sqrt(Delta^2 + (V_b / w)^2),   w = sqrt(K / M),
        tan(phi) = -V_b / (w Delta)

    It returns to v = V_b at the mirror point x_k - Delta after tau_slip = (pi + 2 arctan(V_b / (w Delta)))/w,
    then sticks for 2 Delta / V_b (|K (x_k - Delta)| <= mu_s N holds since mu_k <= mu_s). The cycle reaches
    x_k +- A. (Den Hartog; e.g. Popp & Stelter 1990, Phil. Trans. R. Soc. A 332.)
    """
    if not mu_s > mu_k > 0:
        raise ParameterError(f"mu_k: the classical cycle needs mu_s > mu_k > 0, got mu_s={mu_s}, mu_k={mu_k}")
    w = math.sqrt(stiffness / mass)
    x_k = mu_k * normal_force / stiffness
    delta = (mu_s - mu_k) * normal_force / stiffness
    amplitude = math.hypot(delta, belt_velocity / w)
    slip = (math.pi + 2.0 * math.atan(belt_velocity / (w * delta))) / w
    stick = 2.0 * delta / belt_velocity
    return {
        "period": stick + slip,
        "stick_duration": stick,
        "slip_duration": slip,
        "release_position": x_k + delta,
        "onset_position": x_k - delta,
        "x_max": x_k + amplitude,
        "x_min": x_k - amplitude,
    }
