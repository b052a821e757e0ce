"""Parameters of the mass-on-moving-belt scene (paper Section 2-7, Fig. 1).

All lengths are in mm and times in s, as the paper states them. The paper's units are not mutually
consistent (M in kg, K in N/mm, C in "N.mm/sec", N in N); see :func:`effective_mass` for the two
readings this project supports.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import MISSING, asdict, dataclass, fields, replace

#: How the paper's numbers are read. ``as_given``: every number is used as printed in one equation,
#: as if the units were consistent (this is what reproduces the reported sub-hertz frequencies).
#: ``si``: M [kg] is converted so that forces are in N and lengths in mm (mass coefficient M*1e-3
#: N s^2/mm, C read as N s/mm), which puts the natural frequency at ~11 Hz.
UNIT_READINGS = ("as_given", "si")


class ParameterError(ValueError):
    """A parameter is missing, non-finite or non-physical. The message names the key."""


def checked_number(key: str, value, bound: str | None = None, *, allow_inf: bool = False) -> float:
    """``value`` as a float if it is a finite number within ``bound`` ("positive", "nonnegative" or None;
    ``allow_inf``: +inf too), else ParameterError naming ``key``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ParameterError(f"{key}: expected a number, got {type(value).__name__} {value!r}")
    if math.isnan(value) or (math.isinf(value) and not (allow_inf and value > 0)):
        raise ParameterError(f"{key}: must be finite, got {value!r}")
    if bound == "positive" and not value > 0:
        raise ParameterError(f"{key}: must be > 0, got {value!r}")
    if bound == "nonnegative" and not value >= 0:
        raise ParameterError(f"{key}: must be >= 0, got {value!r}")
    return float(value)


#: The parameters that must be > 0 and >= 0 (the rest, but ``units``, any finite number).
_POSITIVE = ("mass", "stiffness", "normal_force", "mu_s", "plateau_speed")
_NONNEGATIVE = ("damping", "sigma", "belt_velocity", "belt_deceleration")


@dataclass(frozen=True)
class BeltParams:
    """Mass on a moving belt, the paper's 1-DOF stick-slip model."""

    mass: float
    """M, mass [kg] (paper: 1 kg)."""
    stiffness: float
    """K, spring stiffness [N/mm] (paper: 5 N/mm)."""
    damping: float
    """C, viscous damping [N s/mm] (paper prints "N.mm/sec"; 1.5)."""
    mu_s: float
    """Static friction coefficient [1] (paper: 0.5)."""
    sigma: float
    """Friction slope versus relative velocity [s/mm] (paper text 0.3, captions 0.5)."""
    normal_force: float
    """N, normal load [N] (paper: 10 N)."""
    x0: float = 0.0
    """Initial displacement [mm]."""
    v0: float = 0.5
    """Initial velocity [mm/s]."""
    belt_velocity: float = 0.5
    """Belt velocity V_b at t = 0 [mm/s]."""
    belt_deceleration: float = 0.0
    """Belt deceleration [mm/s^2]; the belt speed is max(V_b - d t, 0) (Section 6: 0.025)."""
    units: str = "as_given"
    """Unit reading, one of UNIT_READINGS."""
    plateau_speed: float = math.inf
    """Relative speed [mm/s] beyond which the friction coefficient stays constant (Fig. 17's text: it levels
    off at 0.6 mm/s); inf = the printed law, falling linearly without bound."""

    def __post_init__(self) -> None:
        if self.units not in UNIT_READINGS:
            raise ParameterError(f"units: {self.units!r} is not one of {UNIT_READINGS}")
        for f in (f for f in fields(self) if f.name != "units"):
            bound = "positive" if f.name in _POSITIVE else "nonnegative" if f.name in _NONNEGATIVE else None
            checked_number(f.name, getattr(self, f.name), bound, allow_inf=f.name == "plateau_speed")

    @classmethod
    def from_mapping(cls, values: dict) -> BeltParams:
        """Build from a config mapping; unknown keys are an error naming the key."""
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(values) - known)
        if unknown:
            raise ParameterError(f"{unknown[0]}: unknown parameter (known: {sorted(known)})")
        missing = [f.name for f in fields(cls) if f.name not in values and f.default is MISSING]
        if missing:
            raise ParameterError(f"{missing[0]}: required parameter is missing")
        return cls(**values)

    def with_(self, **changes) -> BeltParams:
        return replace(self, **changes)

    def as_dict(self) -> dict:
        return asdict(self)

    @property
    def effective_mass(self) -> float:
        """Mass coefficient of the equation of motion in the chosen unit reading."""
        return effective_mass(self.mass, self.units)

    @property
    def belt_stop_time(self) -> float:
        """Time at which a decelerating belt comes to rest (inf for a constant belt)."""
        if self.belt_deceleration == 0.0:
            return math.inf
        return self.belt_velocity / self.belt_deceleration

    def belt_velocity_at(self, t):
        """Belt speed V_b(t) [mm/s]: linear deceleration, then at rest."""
        if isinstance(t, float):  # one time (an ODE right-hand side): the same operations in Python floats
            vb = self.belt_velocity - self.belt_deceleration * t
            return vb if vb > 0.0 else (0.0 if vb <= 0.0 else vb)  # np.maximum(vb, 0.0), NaN kept
        import numpy as np

        return np.maximum(self.belt_velocity - self.belt_deceleration * np.asarray(t, dtype=float), 0.0)

    def belt_acceleration_at(self, t):
        """dV_b/dt [mm/s^2] (zero once the belt has stopped)."""
        if isinstance(t, float):  # one time (the exact solver's every segment): the same choice, no array
            return -self.belt_deceleration if t < self.belt_stop_time else 0.0
        import numpy as np

        t = np.asarray(t, dtype=float)
        return np.where(t < self.belt_stop_time, -self.belt_deceleration, 0.0)


def effective_mass(mass: float, units: str) -> float:
    """Mass coefficient in an equation whose forces are in N and lengths in mm.

    ``as_given`` uses the printed number; ``si`` converts kg to N s^2/mm (factor 1e-3).
    """
    if units not in UNIT_READINGS:
        raise ParameterError(f"units: {units!r} is not one of {UNIT_READINGS}")
    return mass if units == "as_given" else mass * 1e-3


#: The paper's baseline (Section 3) with sigma as printed in the text.
PAPER_BASELINE = BeltParams(
    mass=1.0,
    stiffness=5.0,
    damping=1.5,
    mu_s=0.5,
    sigma=0.3,
    normal_force=10.0,
    x0=0.0,
    v0=0.5,
    belt_velocity=0.5,
)
