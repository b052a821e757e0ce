"""Regularized friction: sgn(v_r) replaced by a smooth sign with regularization velocity epsilon.

``tanh``: sgn ~ tanh(v_r / eps); ``arctan``: sgn ~ (2/pi) arctan(v_r / eps). The slope at v_r = 0 is
|a|/eps (tanh) or 2|a|/(pi eps), so the system becomes stiff as eps -> 0 and is integrated with an
implicit method (Radau, BDF, LSODA) given the exact Jacobian. Stick is only approximated: the mass creeps
at the small relative velocity that the regularized friction needs to carry the stick demand.
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from ..model.params import Positive, parameter_set
from .ivp import IvpMethod, IvpSolver

Regularization = Literal["tanh", "arctan"]


def smooth_sign(kind: str, eps: float):
    """(sign, derivative) pair of the regularized sign function (``SmoothedSign`` checks kind and eps)."""
    if kind == "tanh":
        return (lambda u: np.tanh(u / eps)), (lambda u: (1.0 - np.tanh(u / eps) ** 2) / eps)
    return (
        (lambda u: (2.0 / np.pi) * np.arctan(u / eps)),
        (lambda u: (2.0 / np.pi) / (eps * (1.0 + (u / eps) ** 2))),
    )


#: solve_ivp's explicit methods: they take no Jacobian.
EXPLICIT_METHODS = ("RK45", "DOP853", "RK23")


@parameter_set(frozen=False)
class SmoothedSign(IvpSolver):
    regularization: Regularization = "tanh"
    eps: Positive = 1e-3
    """Regularization velocity [mm/s]."""
    method: IvpMethod = "Radau"
    stick_tolerance: Positive = 1e-3
    name: str = "smooth"

    SETTING_NAMES = ("regularization", "eps", "method", "rtol", "atol", "stick_tolerance")

    @property
    def label(self) -> str:
        return f"{self.name}_{self.regularization}_{self.method}"

    def _rhs(self, model):
        sgn, _ = smooth_sign(self.regularization, self.eps)
        return lambda t, y: model.rhs(t, y, sign=sgn)

    def _jac(self, model):
        if self.method in EXPLICIT_METHODS:
            return None
        _, dsgn = smooth_sign(self.regularization, self.eps)
        p, f, m = model.params, model.friction, model.mass

        def jac(t, y):
            vr = y[1] - float(model.belt_velocity(t))
            dfdv = f.a * dsgn(vr) + f.b - p.damping
            return np.array([[0.0, 1.0], [-p.stiffness / m, dfdv / m]])

        return jac
