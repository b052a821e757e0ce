"""Moreau-Jean time stepping with set-valued friction.

Fixed step h, theta-method for the smooth forces, the friction's sign part treated as an impulse
projected onto the static cone [-|a|, |a|] at the end-of-step relative velocity:

    W v1 = W v_free + h r,   r in a Sgn(v1 - V_b(t1)),   W = M + h theta c + K h^2 theta^2

with c = C - b the slip damping. For the attracting (consistent) law this is a monotone inclusion with a
unique closed-form solution: stick (v1 = V_b(t1), exactly) when |v_free - V_b(t1)| <= h|a|/W, otherwise
slip with the full static force. Stick is therefore represented exactly (no creep, no chatter) and the
accuracy is first order (theta = 1) or limited by the non-smooth events (theta = 1/2).
For the printed (repelling) laws the inclusion is not monotone; the sign of v_r at the start of the step
is used instead (documented fallback).
"""

from __future__ import annotations

import numpy as np

from ..model.params import Count, Fraction, Positive, parameter_set
from .base import SLIP_BACKWARD, SLIP_FORWARD, STICK, OneDofSolver, Samples, SolverError, SolverStats


@parameter_set(frozen=False)
class MoreauJean(OneDofSolver):
    h: Positive = 1e-3
    """Time step [s]."""
    theta: Fraction = 0.5
    max_steps: Count = 5_000_000
    name: str = "moreau"
    fixed_step = True  # its work is t_end / h steps, known before the run: it cannot stall

    SETTING_NAMES = ("h", "theta")

    @property
    def label(self) -> str:
        return f"{self.name}_theta{self.theta:g}"

    def _sample(self, steps, t_eval: np.ndarray, belt_velocity) -> Samples:
        """Linear between the step points; each sample takes the phase of the step that contains it."""
        ts, xs, vs, ph = steps
        idx = np.clip(np.searchsorted(ts, t_eval, side="right"), 1, len(ts) - 1)
        return Samples(np.interp(t_eval, ts, xs), np.interp(t_eval, ts, vs), ph[idx - 1].astype(np.int8))

    def _integrate(self, model, t_end: float, stats: SolverStats):
        """The fixed-step march: (step times, x, v at them, the phase of each step)."""
        p, f, m = model.params, model.friction, model.mass
        n = int(np.ceil(t_end / self.h - 1e-9))
        if n > self.max_steps:
            raise SolverError(f"moreau: {n} steps exceed max_steps={self.max_steps}")
        h = t_end / n
        th = self.theta
        c = p.damping - f.b
        k = p.stiffness
        w = m + h * th * c + k * h * h * th * th
        if w <= 0:
            raise SolverError(f"moreau: iteration matrix W={w:.3g} <= 0 (step too large for c={c:.3g})")
        a, a_abs = f.a, abs(f.a)
        attract = f.can_stick
        dv_max = h * a_abs / w
        ts = np.linspace(0.0, t_end, n + 1)
        vbs = p.belt_velocity_at(ts)
        vb_th = p.belt_velocity_at(ts[:-1] + th * h)
        xs = np.empty(n + 1)
        vs = np.empty(n + 1)
        ph = np.empty(n, dtype=np.int8)
        x, v = float(p.x0), float(p.v0)
        xs[0], vs[0] = x, v
        coef_v = m - h * c * (1 - th) - k * h * h * th * (1 - th)
        for i in range(n):
            free = (coef_v * v - h * k * x + h * f.kappa * vb_th[i]) / w
            vb1 = vbs[i + 1]
            g = free - vb1
            if attract:
                if abs(g) <= dv_max:
                    v1, code = vb1, STICK
                elif g > 0:
                    v1, code = free - dv_max, SLIP_FORWARD
                else:
                    v1, code = free + dv_max, SLIP_BACKWARD
            else:
                s = np.sign(v - vbs[i]) or (1.0 if g >= 0 else -1.0)
                v1 = free + h * a * s / w
                code = SLIP_FORWARD if s > 0 else SLIP_BACKWARD
            x = x + h * (th * v1 + (1 - th) * v)
            v = v1
            if not (np.isfinite(x) and abs(x) < 1e12):
                raise SolverError(f"moreau: state diverged at t={ts[i + 1]:.6g}")
            xs[i + 1], vs[i + 1], ph[i] = x, v, code
        stats.steps = n
        stats.rhs_evaluations = n  # one force evaluation per step
        return ts, xs, vs, ph
