"""Unbounded growth: a run whose oscillation keeps growing is the model's answer, not a limit cycle.

The consistent reading's friction mu_s (1 - sigma |v_r|) falls without bound (and reverses sign beyond
|v_r| = 1/sigma), so with negative slip damping some scenes (Fig. 7's C = 0.1, mu_s = 0.8) spiral outwards
for ever. That is a prediction of the equations (two independent integrators retrace it), so it is recorded
apart from a numerical failure: ``BoundedSolver`` wraps any solver so that such a run comes back with
``stats.status = "diverged"`` (``solver_status`` = 2 in its dataset, ``outcome`` = diverged with its
mechanism: stickslip.analysis.outcome); an exception inside the solver stays a numerical failure.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Growth of the steady window's amplitude from its third quarter to its last quarter that counts as
#: unbounded.
GROWTH_FACTOR = 1.05
#: |x| beyond this many static deflections mu_s N / K counts as having left any physical range.
BLOWUP_FACTOR = 1.0e3


def growth_message(t, x, transient: float, static_deflection: float) -> str:
    """'' for a bounded run, otherwise why it counts as diverging."""
    t, x = np.asarray(t, dtype=float), np.asarray(x, dtype=float)
    if not np.all(np.isfinite(x)):
        return "diverged: non-finite displacement"
    big = BLOWUP_FACTOR * max(static_deflection, 1e-12)
    if np.max(np.abs(x)) > big:
        return f"diverged: |x| reached {np.max(np.abs(x)):.3g} mm > {big:.3g} mm"
    t_end = t[-1]
    span = t_end - transient
    if span <= 0:
        return ""
    q3 = (t >= t_end - 0.5 * span) & (t < t_end - 0.25 * span)
    q4 = t >= t_end - 0.25 * span
    if q3.sum() < 2 or q4.sum() < 2:
        return ""
    a3, a4 = np.ptp(x[q3]), np.ptp(x[q4])
    if a4 > GROWTH_FACTOR * a3 and a4 > 1e-9 * big:
        return f"diverging: amplitude still grows ({a3:.4g} -> {a4:.4g} mm over the last half of the run)"
    return ""


def overflowed(exc: Exception) -> bool:
    """An exception raised because the state left the float range (overflow, or NaN/inf met by a root
    search), as opposed to a method that could not proceed."""
    text = str(exc).lower()
    return isinstance(exc, OverflowError | FloatingPointError) or " nan" in text or " inf" in text


@dataclass
class BoundedSolver:
    """Any solver, with unbounded growth turned into a recorded failure."""

    inner: object
    transient: float

    @property
    def name(self):
        return self.inner.name

    @property
    def settings(self):
        return {**self.inner.settings, "divergence_growth_factor": GROWTH_FACTOR}

    def solve(self, model, t_end, t_eval=None):
        try:
            with np.errstate(all="ignore"):
                traj = self.inner.solve(model, t_end, t_eval)
        except (ValueError, ArithmeticError) as exc:  # e.g. a root search on an overflowing segment
            from ..solvers.base import SolverStats, Trajectory, default_t_eval

            t = default_t_eval(t_end, t_eval)  # the samples the inner solver would have returned
            stats = SolverStats(
                status="failed", message=f"numerical failure while integrating: {exc}", failures=1
            )
            if overflowed(exc):  # the state grew past the float range: the model's growth, not the method's
                stats = SolverStats(status="diverged", message=f"diverged: the state overflowed ({exc})")
            return Trajectory.failed(t, model.belt_velocity(t), stats, self.name, self.settings)
        if traj.ok:
            p = model.params
            with np.errstate(all="ignore"):
                msg = growth_message(traj.t, traj.x, self.transient, p.mu_s * p.normal_force / p.stiffness)
            if msg:
                traj.stats.status, traj.stats.message = "diverged", msg
        return traj
