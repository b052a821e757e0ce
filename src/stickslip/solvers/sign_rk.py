"""The paper's method: the single sign-function equation integrated by an explicit Runge-Kutta pair.

``RK45`` is the Dormand-Prince 4(5) pair of MATLAB's ode45; ``DOP853`` the 8(5,3) pair. The right-hand
side is discontinuous at v_r = 0, so the error control, not the model, decides how stick is resolved.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.equations import BeltModel
from .base import Trajectory, reading_model
from .ivp import default_t_eval, integrate


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
        return {
            "method": self.method,
            "rtol": self.rtol,
            "atol": self.atol,
            "max_step": self.max_step,
            "stick_tolerance": self.stick_tolerance,
        }

    def solve(self, model: BeltModel, t_end: float, t_eval=None) -> Trajectory:
        model = reading_model(model, self.name)
        return integrate(
            model,
            model.rhs,
            t_end,
            default_t_eval(t_end, t_eval),
            method=self.method,
            rtol=self.rtol,
            atol=self.atol,
            max_step=self.max_step,
            stick_tolerance=self.stick_tolerance,
            label=f"{self.name}_{self.method}",
            settings=self.settings,
        )
