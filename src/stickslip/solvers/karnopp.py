"""Karnopp's stick-band model: inside |v_r| < eta the friction is whatever keeps the relative
acceleration zero, saturated at the static limit; outside, the slip law. The right-hand side stays
bounded but is still discontinuous at the band edges; it is integrated with an explicit Runge-Kutta pair.

Inside the band the relative velocity is frozen at its entry value (not zero), so the mass creeps
relative to the belt by up to eta times the stick time: Karnopp's characteristic stick error.
For the printed (repelling) variants there is no stick and the plain sign law is used.
"""

from __future__ import annotations

import numpy as np

from ..model.params import Positive, parameter_set
from .ivp import IvpSolver


@parameter_set(frozen=False)
class Karnopp(IvpSolver):
    eta: Positive = 1e-3
    """Half-width of the stick band [mm/s]."""
    name: str = "karnopp"

    SETTING_NAMES = ("eta", "method", "rtol", "atol")

    def _stick_band(self) -> float:
        return self.eta  # the band is where this method sticks

    def _rhs(self, model):
        p, f, m = model.params, model.friction, model.mass
        a_abs = abs(f.a)
        eta = self.eta
        sticky = f.can_stick

        def rhs(t, y):
            x, v = y
            vb = float(p.belt_velocity_at(t))
            if sticky and abs(v - vb) < eta:
                smooth = f.b * v + f.kappa * vb - p.damping * v - p.stiffness * x
                demand = m * float(p.belt_acceleration_at(t)) - smooth  # sign-part force for v_r' = 0
                s_eff = min(max(demand, -a_abs), a_abs) / f.a
                return np.array([v, model.acceleration(t, x, v, sign=lambda _u: s_eff)])
            return np.array([v, model.acceleration(t, x, v)])

        return rhs
