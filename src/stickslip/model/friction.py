"""Friction laws of the 1-DOF model: the paper's Eq. 2-4 as printed and the physically consistent reading.

All variants share one affine-in-velocity form during slip,

    F(v, t) = a * sgn(v_r) + b * v + kappa * V_b(t),      v_r = v - V_b(t),

which keeps every slip segment a linear ODE with constant coefficients (used by the exact solver) and lets
one right-hand side serve all variants. F is the force on the mass in the +x direction.

``eq3_printed``  F = mu_s N (sgn(v_r) - sigma v_r)          (Eq. 2/3 as printed)
``eq4_printed``  Eq. 4 as printed: the mu_s N factor is missing from the sigma V_b term
``consistent``   F = -mu_s N (sgn(v_r) - sigma v_r): friction drives the mass toward the belt velocity,
                 its magnitude mu_s N (1 - sigma |v_r|) falling linearly with the relative speed

Optionally the affine part saturates: beyond a relative speed ``plateau_speed`` (v_p) the law uses
v_r clipped to +-v_p, so the coefficient levels off (the plateau Fig. 17's text describes). Slip is then
piecewise affine with one more switching surface, |v_r| = v_p, which the exact solver handles as an event.

The printed sign makes friction push the mass *away* from the belt velocity, so v_r = 0 repels and the
printed variants cannot stick at all (see ``can_stick``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

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
    plateau_speed: float = float("inf")
    """|v_r| [mm/s] beyond which the affine part stops changing (inf: no plateau)."""

    @cached_property
    def has_plateau(self) -> bool:
        return bool(np.isfinite(self.plateau_speed))

    def outer(self, s: int) -> tuple[float, float, float]:
        """Beyond the plateau on side s: (slip damping coefficient b', constant force, V_b coefficient).

        F = a s + b (s v_p) + (b + kappa) V_b: no velocity dependence left, so the slip damping is C alone.
        """
        return 0.0, self.a * s + self.b * s * self.plateau_speed, self.b + self.kappa

    @property
    def can_stick(self) -> bool:
        """Stick (a sliding mode on v_r = 0) attracts only if friction opposes the relative velocity."""
        return self.a < 0

    def force(self, v, vb, sign=np.sign):
        """Friction force for mass velocity v and belt velocity vb; ``sign`` may be a smoothed sign."""
        if isinstance(v, float) and isinstance(vb, float):
            return self._scalar_force(v, vb, sign)
        v = np.asarray(v, dtype=float)
        if self.has_plateau:
            vr = np.clip(v - vb, -self.plateau_speed, self.plateau_speed)
            return self.a * sign(v - vb) + self.b * vr + (self.b + self.kappa) * vb
        return self.a * sign(v - vb) + self.b * v + self.kappa * vb

    def _scalar_force(self, v: float, vb: float, sign) -> float:
        """``force`` for one state (Python floats), the same operations in the same order: an ODE solver
        calls it once per right-hand side, where numpy's per-call overhead on 0-d values dominated."""
        d = v - vb
        s = _sign(d) if sign is np.sign else sign(d)
        if self.has_plateau:
            vp = self.plateau_speed
            vr = -vp if d < -vp else (vp if d > vp else d)  # np.clip, -0.0 and NaN kept
            return self.a * s + self.b * vr + (self.b + self.kappa) * vb
        return self.a * s + self.b * v + self.kappa * vb


def _sign(d: float) -> float:
    """np.sign of one float: -1, 0 (also for -0.0) or 1; NaN stays NaN."""
    return 1.0 if d > 0.0 else (-1.0 if d < 0.0 else (0.0 if d == 0.0 else d))


def friction_law(params: BeltParams, variant: str) -> AffineFriction:
    """The friction law of ``variant`` for the given parameters."""
    mu_n = params.mu_s * params.normal_force
    s = params.sigma
    vp = float(getattr(params, "plateau_speed", float("inf")))
    if variant == "eq3_printed":
        return AffineFriction(variant, a=mu_n, b=-mu_n * s, kappa=mu_n * s, plateau_speed=vp)
    if variant == "eq4_printed":
        return AffineFriction(variant, a=mu_n, b=-mu_n * s, kappa=s, plateau_speed=vp)
    if variant == "consistent":
        return AffineFriction(variant, a=-mu_n, b=mu_n * s, kappa=-mu_n * s, plateau_speed=vp)
    raise ParameterError(f"variant: {variant!r} is not one of {VARIANTS}")
