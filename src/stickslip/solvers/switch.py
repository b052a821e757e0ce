"""Event-driven switch-model solver for any friction law (``model/laws.py``).

The motion is a sequence of phases, as in the exact solver (``exact.py``), but slip may follow any law:

* **slip** in direction s = sgn(v_r): M x'' + C x' + K x = -N s mu(s v_r), integrated with a high-order
  Runge-Kutta method (scipy's DOP853, tight tolerances, dense output). The law is evaluated through its
  smooth continuation in s v_r, so the right-hand side stays smooth while the integrator locates the end
  of the phase: the event s v_r = 0 (direction: falling), found by root finding on the dense output.
  Relative speeds where the law is not smooth (the affine plateau) are events too; integration restarts
  there so no step straddles a kink.
* **at v_r = 0** the friction is set-valued, F in [-N mu_static, N mu_static]. With D = M a_b + C V_b + K x,
  the force friction must supply to keep the mass on the belt: |D| <= N mu_static -> stick; D > N mu_static
  -> slip backward; D < -N mu_static -> slip forward. Arriving from slip with |D| > N mu_static, the mass
  passes through v_r = 0 into slip the other way.
* **stick** is exact: x moves with the belt (quadratic in time for a decelerating belt), D is quadratic in
  time, and release is the first root of |D| = N mu_static in closed form (shared with ``exact.py``).

Grazing returns (v_r touching 0 without crossing: no sign change for the event finder) are caught at the
minima of s v_r, located as the rising zeros of the relative acceleration: a minimum within
``graze_tolerance`` (relative to the velocity scale) of 0 ends the slip there, as in the exact solver. The
undamped-slip case C = b (the paper's text baseline, sigma = 0.3) grazes on every cycle.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ..model.equations import BeltModel
from ..model.laws import LawModel
from ..model.params import Count, ParameterError, Positive, parameter_set
from .base import STICK, SolverError
from .events import EventDrivenSolver, Segment
from .exact import stick_or_slip, stick_segment

#: solve_ivp methods a slip phase may use.
SwitchMethod = Literal["DOP853", "RK45", "Radau", "LSODA"]


@dataclass(frozen=True)
class DenseMotion:
    """A slip phase's dense output, as (x, v) at local time tau (the Segment interface)."""

    solution: object  # scipy OdeSolution
    t0: float

    def state(self, tau):
        y = self.solution(self.t0 + np.asarray(tau, dtype=float))
        return y[0], y[1]


def as_law_model(model) -> LawModel:
    """A ``LawModel`` from either a LawModel or a BeltModel of the ``consistent`` reading."""
    if isinstance(model, LawModel):
        return model
    if isinstance(model, BeltModel):
        return LawModel.from_belt_model(model)
    if hasattr(model, "law") and hasattr(model, "params"):  # a wrapper, e.g. the work-budget proxy
        return LawModel(model.params, model.law)
    raise ParameterError(f"model: expected a LawModel or BeltModel, got {type(model).__name__}")


@parameter_set(frozen=False)
class SwitchSolver(EventDrivenSolver):
    """Switch-model solver; ``rtol``/``atol`` are DOP853's tolerances on (x [mm], v [mm/s])."""

    rtol: Positive = 1e-12
    atol: Positive = 1e-13
    graze_tolerance: Positive = 1e-10
    """A minimum of |v_r| below this fraction of the velocity scale is a return to v_r = 0 (a graze)."""
    method: SwitchMethod = "DOP853"
    max_segments: Count = 200_000
    max_zero_length: Count = 50
    name: str = "switch"

    SETTING_NAMES = ("rtol", "atol", "method", "graze_tolerance")

    def _integrated(self, model) -> LawModel:
        return as_law_model(model)

    def _solve_settings(self, model) -> dict:
        return {**self.settings, "law": model.law.describe()}

    def _contact_decision(self, lm, t, x):
        return contact_decision(lm, t, x)

    def _phase(self, lm, mode, t, x, v, t_limit, stats):
        if mode == STICK:
            phase = self._stick(lm, t, x, t_limit)
            stats.steps += 1  # a slip phase counts its integrator's steps
            return phase
        return self._slip(lm, t, x, v, mode, t_limit, stats)

    # -- phases ---------------------------------------------------------------------------------------
    @staticmethod
    def _stick(lm: LawModel, t0: float, x0: float, t_limit: float):
        d0 = float(lm.stick_demand(t0, x0))
        segment, release = stick_segment(lm.params, t0, x0, t_limit, d0, lm.params.damping, lm.static_force)
        return segment, STICK if release is None else release

    def _slip(self, lm: LawModel, t0: float, x0: float, v0: float, s: int, t_limit: float, stats):
        """One slip phase in direction s; it ends at v_r = 0 ('contact'), a law breakpoint or t_limit."""
        from scipy.integrate import solve_ivp  # here: the parse-time config check builds every solver

        vb = lm.belt_velocity

        def rhs(t, y):
            return np.array([y[1], lm.acceleration(t, y[0], y[1], s)])

        def contact(t, y):
            return s * (y[1] - float(vb(t)))

        contact.terminal, contact.direction = True, -1

        def turning(t, y):  # relative acceleration: its rising zeros are the minima of s v_r
            return s * (lm.acceleration(t, y[0], y[1], s) - float(lm.params.belt_acceleration_at(t)))

        turning.terminal, turning.direction = False, 1
        events = [contact, turning]
        nodes = lm.law.breakpoints
        if nodes:  # the law is smooth between its breakpoints: leave the interval -> restart there
            rel0 = s * (v0 - float(vb(t0)))
            rate0 = s * (float(rhs(t0, [x0, v0])[1]) - float(lm.params.belt_acceleration_at(t0)))
            lo, hi = smooth_interval(nodes, rel0, rate0)

            def leave(t, y):
                rel = s * (y[1] - float(vb(t)))
                return min(rel - lo, hi - rel)

            leave.terminal, leave.direction = True, -1
            events.append(leave)
        sol = solve_ivp(
            rhs,
            (t0, t_limit),
            [x0, v0],
            method=self.method,
            rtol=self.rtol,
            atol=self.atol,
            dense_output=True,
            events=events,
        )
        if sol.status < 0:
            raise SolverError(f"switch solver: slip phase from t={t0:.17g} failed: {sol.message}")
        stats.rhs_evaluations += int(sol.nfev)
        stats.steps += len(sol.t) - 1
        t1 = float(sol.t[-1])
        motion = DenseMotion(sol.sol, t0)
        # a graze: s v_r touches 0 at a minimum without crossing (no sign change for the event finder)
        scale = max(abs(v0), abs(float(vb(t0))), lm.static_force / math.sqrt(lm.params.stiffness * lm.mass))
        for t_min, y_min in zip(sol.t_events[1], sol.y_events[1]):
            if t0 < t_min < t1 and s * (y_min[1] - float(vb(t_min))) <= self.graze_tolerance * scale:
                stats.events += 1
                return Segment(t0, float(t_min), s, motion), "contact"
        if sol.status == 1:  # v_r = 0, or a breakpoint of the law (same direction, fresh integration)
            stats.events += 1
            return Segment(t0, t1, s, motion), "contact" if len(sol.t_events[0]) else s
        return Segment(t0, t1, s, motion), s


def smooth_interval(nodes: tuple[float, ...], rel: float, rate: float) -> tuple[float, float]:
    """(lo, hi): the interval between breakpoints that the relative speed ``rel`` is in, or, on a
    breakpoint (a restart there), the one it moves into (by the sign of its rate)."""

    def node(j):
        return -math.inf if j < 0 else (math.inf if j >= len(nodes) else nodes[j])

    i = bisect.bisect_left(nodes, rel)  # nodes[i-1] < rel <= nodes[i]
    for j in (i - 1, i):  # on (within round-off of) a node: go the way the speed moves
        if 0 <= j < len(nodes) and abs(nodes[j] - rel) <= 1e-9 * max(nodes[j], abs(rel)):
            return (nodes[j], node(j + 1)) if rate >= 0 else (node(j - 1), nodes[j])
    return node(i - 1), node(i)


def contact_decision(lm: LawModel, t: float, x: float):
    """Stick or the slip direction at v_r = 0: the set-valued static friction decides."""
    return stick_or_slip(float(lm.stick_demand(t, x)), lm.static_force)
