"""The paper's method: the single sign-function equation integrated by an explicit Runge-Kutta pair.

``RK45`` is the Dormand-Prince 4(5) pair of MATLAB's ode45; ``DOP853`` the 8(5,3) pair. The right-hand
side is discontinuous at v_r = 0, so the error control, not the model, decides how stick is resolved.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from ..model.equations import BeltModel
from .base import SolverStats, Timer, Trajectory, classify_phase


@dataclass
class SignRungeKutta:
    method: str = "RK45"
    rtol: float = 1e-3
    atol: float = 1e-6
    max_step: float = np.inf
    stick_tolerance: float = 1e-3
    """|v - V_b| [mm/s] below which a sample is labelled stick (the method itself has no stick state)."""
    name: str = "sign_rk"

    @property
    def settings(self) -> dict:
        return {"method": self.method, "rtol": self.rtol, "atol": self.atol,
                "max_step": self.max_step, "stick_tolerance": self.stick_tolerance}

    def solve(self, model: BeltModel, t_end: float, t_eval=None) -> Trajectory:
        if t_eval is None:
            t_eval = np.linspace(0.0, t_end, 2001)
        t_eval = np.asarray(t_eval, dtype=float)
        calls = 0

        def rhs(t, y):
            nonlocal calls
            calls += 1
            return model.rhs(t, y)

        stats = SolverStats()
        y0 = [model.params.x0, model.params.v0]
        with Timer() as timer:
            sol = solve_ivp(rhs, (0.0, t_end), y0, method=self.method, rtol=self.rtol, atol=self.atol,
                            max_step=self.max_step, dense_output=True)
        stats.cpu_time = timer.elapsed
        stats.rhs_evaluations = calls
        stats.steps = max(len(sol.t) - 1, 0)
        if not sol.success:
            stats.status, stats.message, stats.failures = "failed", str(sol.message), 1
            x = np.full(t_eval.shape, np.nan)
            v = np.full(t_eval.shape, np.nan)
        else:
            x, v = sol.sol(t_eval)
            if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
                stats.status, stats.message, stats.failures = "failed", "non-finite state", 1
        vb = model.belt_velocity(t_eval)
        return Trajectory(
            t=t_eval, x=x, v=v, phase=classify_phase(v, vb, self.stick_tolerance), belt_velocity=vb,
            stats=stats, method=f"{self.name}_{self.method}", settings=self.settings,
        )
