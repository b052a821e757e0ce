"""Regularized friction: sgn(v_r) replaced by a smooth sign with regularization velocity epsilon.

``tanh``: sgn ~ tanh(v_r / eps); ``arctan``: sgn ~ (2/pi) arctan(v_r / eps). The slope at v_r = 0 is
|a|/eps (tanh) or 2|a|/(pi eps), so the system becomes stiff as eps -> 0 and is integrated with an
implicit method (Radau, BDF, LSODA) given the exact Jacobian. Stick is only approximated: the mass creeps
at the small relative velocity that the regularized friction needs to carry the stick demand.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from ..model.equations import BeltModel
from .base import SolverStats, Timer, Trajectory, classify_phase

REGULARIZATIONS = ("tanh", "arctan")


def smooth_sign(kind: str, eps: float):
    """(sign, derivative) pair of the regularized sign function."""
    if eps <= 0:
        raise ValueError(f"eps: must be > 0, got {eps!r}")
    if kind == "tanh":
        return (lambda u: np.tanh(u / eps)), (lambda u: (1.0 - np.tanh(u / eps) ** 2) / eps)
    if kind == "arctan":
        return ((lambda u: (2.0 / np.pi) * np.arctan(u / eps)),
                (lambda u: (2.0 / np.pi) / (eps * (1.0 + (u / eps) ** 2))))
    raise ValueError(f"regularization: {kind!r} is not one of {REGULARIZATIONS}")


@dataclass
class SmoothedSign:
    regularization: str = "tanh"
    eps: float = 1e-3
    """Regularization velocity [mm/s]."""
    method: str = "Radau"
    rtol: float = 1e-6
    atol: float = 1e-9
    max_step: float = np.inf
    stick_tolerance: float = 1e-3
    name: str = "smooth"

    @property
    def settings(self) -> dict:
        return {"regularization": self.regularization, "eps": self.eps, "method": self.method,
                "rtol": self.rtol, "atol": self.atol, "stick_tolerance": self.stick_tolerance}

    def solve(self, model: BeltModel, t_end: float, t_eval=None) -> Trajectory:
        if t_eval is None:
            t_eval = np.linspace(0.0, t_end, 2001)
        t_eval = np.asarray(t_eval, dtype=float)
        sgn, dsgn = smooth_sign(self.regularization, self.eps)
        p, f, m = model.params, model.friction, model.mass
        calls = 0
        jac_calls = 0

        def rhs(t, y):
            nonlocal calls
            calls += 1
            return model.rhs(t, y, sign=sgn)

        def jac(t, y):
            nonlocal jac_calls
            jac_calls += 1
            vr = y[1] - float(model.belt_velocity(t))
            dfdv = f.a * dsgn(vr) + f.b - p.damping
            return np.array([[0.0, 1.0], [-p.stiffness / m, dfdv / m]])

        stats = SolverStats()
        kwargs = {} if self.method in ("RK45", "DOP853", "RK23") else {"jac": jac}
        with Timer() as timer:
            try:
                sol = solve_ivp(rhs, (0.0, t_end), [p.x0, p.v0], method=self.method, rtol=self.rtol,
                                atol=self.atol, max_step=self.max_step, dense_output=True, **kwargs)
            except (ValueError, ArithmeticError) as exc:  # e.g. non-finite Jacobian
                sol = None
                stats.message = f"{type(exc).__name__}: {exc}"
        stats.cpu_time = timer.elapsed
        stats.rhs_evaluations = calls
        stats.jacobian_evaluations = jac_calls
        if sol is None or not sol.success:
            stats.status, stats.failures = "failed", 1
            stats.message = stats.message or str(sol.message)
            x = np.full(t_eval.shape, np.nan)
            v = np.full(t_eval.shape, np.nan)
        else:
            stats.steps = max(len(sol.t) - 1, 0)
            stats.min_step = float(np.min(np.diff(sol.t))) if len(sol.t) > 1 else float("nan")
            x, v = sol.sol(t_eval)
            if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
                stats.status, stats.message, stats.failures = "failed", "non-finite state", 1
        vb = model.belt_velocity(t_eval)
        return Trajectory(
            t=t_eval, x=x, v=v, phase=classify_phase(v, vb, self.stick_tolerance), belt_velocity=vb,
            stats=stats, method=f"{self.name}_{self.regularization}_{self.method}", settings=self.settings,
        )
