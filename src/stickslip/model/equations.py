"""The single equation of motion (paper Eq. 1-5): M x'' + C x' + K x = F(x', t)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .friction import AffineFriction, friction_law
from .params import BeltParams


@dataclass(frozen=True)
class BeltModel:
    """A mass on a (possibly decelerating) belt with one of the friction variants."""

    params: BeltParams
    friction: AffineFriction

    @classmethod
    def build(cls, params: BeltParams, variant: str) -> BeltModel:
        return cls(params, friction_law(params, variant))

    @property
    def variant(self) -> str:
        return self.friction.variant

    @property
    def mass(self) -> float:
        return self.params.effective_mass

    def belt_velocity(self, t):
        return self.params.belt_velocity_at(t)

    def acceleration(self, t, x, v, sign=np.sign):
        """x'' from the single equation with the given (possibly smoothed) sign function."""
        p = self.params
        vb = self.belt_velocity(t)
        force = self.friction.force(v, vb, sign=sign)
        return (force - p.damping * v - p.stiffness * x) / self.mass

    def rhs(self, t, y, sign=np.sign):
        """First-order form y = (x, v) for ODE solvers (the paper's ode45 right-hand side).

        The state goes in as Python floats, so the belt speed and friction take their one-state paths (same
        operations, same bits): the stalled runs of the methods study make 250 000 calls, where numpy's
        overhead on 0-d values was half the cost of a run."""
        return np.array([y[1], self.acceleration(float(t), float(y[0]), float(y[1]), sign=sign)])

    # -- quantities of the non-smooth (set-valued) model used by the exact solver -----------------
    def stick_demand(self, t, x):
        """D = (force needed to move with the belt) - (friction's smooth part) at v = V_b.

        The mass can stay stuck while |D| <= |a|; relative acceleration on side s is (a s - D)/M.
        """
        p = self.params
        vb = self.belt_velocity(t)
        needed = self.mass * p.belt_acceleration_at(t) + p.damping * vb + p.stiffness * x
        return needed - (self.friction.b + self.friction.kappa) * vb

    def slip_damping(self) -> float:
        """Effective viscous coefficient during slip, C - b (negative: friction pumps energy in)."""
        return self.params.damping - self.friction.b

    def stick_release_position(self) -> float:
        """x at which a constant-belt stick ends (D = |a|), for the attracting variants."""
        p = self.params
        vb = p.belt_velocity
        return (
            abs(self.friction.a) + (self.friction.b + self.friction.kappa) * vb - p.damping * vb
        ) / p.stiffness
