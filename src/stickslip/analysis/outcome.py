"""What a run of the model did, and why, from closed form: its answer to the paper, whatever it is.

A run ends in one of five outcomes. Four are the model's prediction and decide a claim about a bounded
stick-slip oscillation (amplitude, stick time, frequency...): ``stick_slip`` (the oscillation the paper
shows), ``no_stick`` (a bounded oscillation that never returns to v_r = 0), ``rest`` (steady sliding: the
mass settles while the belt moves on) and ``diverged`` (the motion grows without bound). Only ``failed``,
a numerical failure, computed nothing.

``mechanism`` says why in one sentence from the equations of the slip phase, M x'' + (C - b) x' + K x =
a sgn(v_r) + kappa V_b (stickslip.model.friction), so a reader sees the cause, not only that a number is
missing.
"""

from __future__ import annotations

import math

import numpy as np

from ..solvers.base import STICK

OUTCOMES = ("stick_slip", "no_stick", "rest", "diverged", "failed")
#: Outcomes that are the model's answer although no stick-slip cycle exists to measure.
ANSWERS = ("no_stick", "rest", "diverged")
#: The steady window has come to rest when its displacement range is below this fraction of the run's.
REST_FRACTION = 1e-4
#: CF flag attributes of the ``outcome`` variable.
FLAG_ATTRS = {
    "flag_values": np.arange(len(OUTCOMES), dtype=np.int8),
    "flag_meanings": " ".join(OUTCOMES),
}


def outcome_code(name: str) -> int:
    return OUTCOMES.index(name)


def outcome_name(code: float) -> str:
    """The outcome of a stored code; '' for NaN (no run)."""
    return OUTCOMES[int(code)] if math.isfinite(code) else ""


def run_outcome(traj, transient: float) -> str:
    """The outcome of one trajectory (its steady window is t >= ``transient``)."""
    if traj.stats.status == "diverged":
        return "diverged"
    x = np.asarray(traj.x, dtype=float)
    if traj.stats.status != "ok" or not np.all(np.isfinite(x)):
        return "failed"
    window = np.asarray(traj.t) >= transient
    if np.any(np.asarray(traj.phase)[window] == STICK):
        return "stick_slip"
    span = float(np.ptp(x[window])) if window.any() else 0.0
    return "rest" if span <= REST_FRACTION * max(float(np.ptp(x)), 1e-300) else "no_stick"


def _g(value: float) -> str:
    return f"{value:.3g}"


def _slip_damping_clause(model) -> str:
    """'slip damping C - mu_s N sigma = 1.5 - 4 = -2.5 N s/mm < 0' with its sign's meaning, for the affine
    readings (the friction's velocity coefficient b is +mu_s N sigma in the consistent reading, -mu_s N sigma
    as printed)."""
    c, b = model.params.damping, model.friction.b
    gamma = model.slip_damping()
    op = "-" if b > 0 else "+"
    formula = f"C {op} mu_s N sigma = {_g(c)} {op} {_g(abs(b))} = {_g(gamma)}"
    formula = f"C = {_g(gamma)}" if b == 0 else formula
    effect = "< 0 pumps energy in" if gamma < 0 else "> 0 drains energy"
    return f"slip damping {formula} N s/mm {effect}"


def mechanism(model, outcome: str, max_velocity: float = float("nan"), message: str = "") -> str:
    """One sentence: why the model ends in ``outcome``, from the slip-phase equation's coefficients.

    ``max_velocity``: the largest mass velocity of the steady window (for ``no_stick``); ``message``: the
    solver's or divergence guard's words (for ``diverged`` and ``failed``)."""
    if outcome == "failed":
        return f"numerical failure, nothing computed ({message})" if message else "numerical failure"
    if outcome == "stick_slip":
        return "stick-slip cycle"
    friction = getattr(model, "friction", None)
    p = model.params
    if friction is None:  # a general friction law (model.laws): no closed-form slip coefficients
        return _law_mechanism(model, outcome, max_velocity, message)
    repels = not friction.can_stick
    repel_clause = (
        f"friction pushes the mass away from the belt speed (a = +{_g(friction.a)} N), so v_r = 0 repels"
        if repels
        else ""
    )
    if outcome == "diverged":
        parts = [_slip_damping_clause(model)]
        if friction.variant == "consistent" and not friction.has_plateau and p.sigma > 0:
            parts.append(f"friction reverses beyond |v_r| = 1/sigma = {_g(1 / p.sigma)} mm/s")
        elif repels:
            parts.append(repel_clause)
        return "; ".join(parts) + ": the motion grows without bound"
    if outcome == "rest":
        x_rest = friction.force(0.0, float(p.belt_velocity)) / p.stiffness if p.belt_velocity > 0 else 0.0
        lead = repel_clause + " and " if repels else ""
        return (
            f"{lead}{_slip_damping_clause(model)}: steady sliding at x = {_g(x_rest)} mm is stable, "
            "the mass comes to rest without sticking"
        )
    if outcome == "no_stick":
        if repels:
            return f"{repel_clause}: the mass oscillates in slip and never sticks"
        return (
            f"the oscillation's largest mass velocity {_g(max_velocity)} mm/s stays below the belt speed "
            f"{_g(p.belt_velocity)} mm/s, so v_r never returns to 0: the mass never sticks"
        )
    raise ValueError(f"outcome: {outcome!r} is not one of {OUTCOMES}")


def _law_mechanism(model, outcome: str, max_velocity: float, message: str) -> str:
    law = getattr(model, "law", None)
    kind = getattr(law, "kind", "friction law")
    if outcome == "diverged":
        return f"with the {kind} law the motion grows without bound ({message})"
    if outcome == "rest":
        return f"with the {kind} law steady sliding is stable: the mass comes to rest without sticking"
    return (
        f"with the {kind} law the oscillation's largest mass velocity {_g(max_velocity)} mm/s stays below "
        f"the belt speed {_g(model.params.belt_velocity)} mm/s: the mass never sticks"
    )
