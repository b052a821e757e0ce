"""The paper's method: the single sign-function equation integrated by an explicit Runge-Kutta pair.

``RK45`` is the Dormand-Prince 4(5) pair of MATLAB's ode45; ``DOP853`` the 8(5,3) pair. The right-hand
side is discontinuous at v_r = 0, so the error control, not the model, decides how stick is resolved.
"""

from __future__ import annotations

from ..model.params import Positive, parameter_set
from .ivp import IvpSolver


@parameter_set(frozen=False)
class SignRungeKutta(IvpSolver):
    rtol: Positive = 1e-3
    atol: Positive = 1e-6
    stick_tolerance: Positive = 1e-3
    """|v - V_b| [mm/s] below which a sample is labelled stick (the method itself has no stick state)."""
    name: str = "sign_rk"

    SETTING_NAMES = ("method", "rtol", "atol", "max_step", "stick_tolerance")

    def _rhs(self, model):
        return model.rhs
