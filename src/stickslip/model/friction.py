"""Friction laws of the 1-DOF model: the paper's Eq. 2-4 as printed and the physically consistent reading.

All variants share one affine-in-velocity form during slip,

    F(v, t) = a * sgn(v_r) + b * v + kappa * V_b(t),      v_r = v - V_b(t),

which keeps every slip segment a linear ODE with constant coefficients (used by the exact solver) and lets
one right-hand side serve all variants. F is the force on the mass in the +x direction.

``eq3_printed``  F = mu_s N (sgn(v_r) - sigma v_r)          (Eq. 2/3 as printed)
``eq4_printed``  Eq. 4 as printed: the mu_s N factor is missing from the sigma V_b term
``consistent``   F = -mu_s N (sgn(v_r) - sigma v_r): friction drives the mass toward the belt velocity,
                 its magnitude mu_s N (1 - sigma |v_r|) falling linearly with the relative speed

The printed sign makes friction push the mass *away* from the belt velocity, so v_r = 0 repels and the
printed variants cannot stick at all (see ``can_stick``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .params import BeltParams, ParameterError

VARIANTS = ("eq3_printed", "eq4_printed", "consistent")


@dataclass(frozen=True)
class AffineFriction:
    """F = a sgn(v_r) + b v + kappa V_b(t) [N]."""

    variant: str
    a: float
    """Coefficient of sgn(v_r) [N]; a < 0 opposes the relative velocity (attracting stick)."""
    b: float
    """Coefficient of the mass velocity [N s/mm]; enters the slip damping as C - b."""
    kappa: float
    """Coefficient of the belt velocity [N s/mm]."""

    @property
    def can_stick(self) -> bool:
        """Stick (a sliding mode on v_r = 0) attracts only if friction opposes the relative velocity."""
        return self.a < 0

    def force(self, v, vb, sign=np.sign):
        """Friction force for mass velocity v and belt velocity vb; ``sign`` may be a smoothed sign."""
        v = np.asarray(v, dtype=float)
        return self.a * sign(v - vb) + self.b * v + self.kappa * vb

    def coefficient(self, v, vb, normal_force: float):
        """Signed friction coefficient F/N along a trajectory (Fig. 17)."""
        return self.force(v, vb) / normal_force


def friction_law(params: BeltParams, variant: str) -> AffineFriction:
    """The friction law of ``variant`` for the given parameters."""
    mu_n = params.mu_s * params.normal_force
    s = params.sigma
    if variant == "eq3_printed":
        return AffineFriction(variant, a=mu_n, b=-mu_n * s, kappa=mu_n * s)
    if variant == "eq4_printed":
        return AffineFriction(variant, a=mu_n, b=-mu_n * s, kappa=s)
    if variant == "consistent":
        return AffineFriction(variant, a=-mu_n, b=mu_n * s, kappa=-mu_n * s)
    raise ParameterError(f"variant: {variant!r} is not one of {VARIANTS}")


def friction_coefficient_consistent(relative_speed, mu_s: float, sigma: float):
    """|mu|(|v_r|) of the consistent reading: mu_s (1 - sigma |v_r|), unbounded linear fall."""
    return mu_s * (1.0 - sigma * np.abs(relative_speed))
