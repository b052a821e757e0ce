"""Frozen, validated parameter sets for the beam-on-rotating-disc scene (paper Sections 8-12).

Internal unit system (consistent): length mm, time s, force N, mass t (tonne = 1e3 kg), stress MPa.
Config values are given in engineering units (GPa, kg m-3, m s-2, rev/min, mm/s) and converted here.
Every validation error is a ``ValueError`` whose message starts with the offending key.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np

CONTACT_METHODS = ("kinematic", "penalty", "fixed_normal")
MASS_KINDS = ("lumped", "consistent")
INITIAL_STATES = ("static", "drop", "undeformed")  # "undeformed" = "drop" (kept for old configs)
OUTPUT_NODES = ("free_end_lower", "free_end_axis", "free_end_upper")
DISC_DIRECTIONS = ("clockwise", "counterclockwise")


def _positive(name: str, value: float) -> None:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise ValueError(f"{name}: must be a positive finite number, got {value!r}")


def _from_mapping(cls, data: Mapping[str, Any], prefix: str):
    names = {f.name for f in fields(cls)}
    unknown = set(data) - names
    if unknown:
        raise ValueError(f"{prefix}{sorted(unknown)[0]}: unknown key for {cls.__name__}")
    return cls(**dict(data))


@dataclass(frozen=True)
class BeamParams:
    """Clamped-free elastic beam (pad back-plate), 2-D frame elements, 3 DOF/node (u, v, theta)."""

    length: float = 100.0  #: beam length L [mm]
    thickness: float = 1.0  #: beam thickness h (in-plane, bending direction) [mm]
    width: float = 1.0  #: out-of-plane width b [mm] (assumption: the paper gives none)
    youngs_modulus_gpa: float = 210.0  #: E [GPa] (steel back plate, assumption)
    density_kg_m3: float = 7850.0  #: rho [kg m-3] (steel, assumption)
    poisson_ratio: float = 0.3  #: nu [-] (recorded only; Euler-Bernoulli elements do not use it)
    gravity_m_s2: float = 9.81  #: g [m s-2], the only normal load
    n_elements: int = 20  #: number of beam elements [-]
    mass: str = "lumped"  #: "lumped" (HRZ diagonal, as explicit codes) or "consistent"
    #: rotary inertia rho*I of the cross-sections (Rayleigh beam). Needed for contact at the lower face:
    #: without it the tangential inertia of the face point vanishes under mesh refinement.
    rotary_inertia: bool = True

    def __post_init__(self) -> None:
        for k in ("length", "thickness", "width", "youngs_modulus_gpa", "density_kg_m3"):
            _positive(k, getattr(self, k))
        if not (0.0 <= self.poisson_ratio < 0.5):
            raise ValueError(f"poisson_ratio: must lie in [0, 0.5), got {self.poisson_ratio!r}")
        if not (self.gravity_m_s2 >= 0 and math.isfinite(self.gravity_m_s2)):
            raise ValueError(f"gravity_m_s2: must be >= 0, got {self.gravity_m_s2!r}")
        if not (isinstance(self.n_elements, int) and self.n_elements >= 1):
            raise ValueError(f"n_elements: must be an integer >= 1, got {self.n_elements!r}")
        if self.mass not in MASS_KINDS:
            raise ValueError(f"mass: must be one of {MASS_KINDS}, got {self.mass!r}")
        if not isinstance(self.rotary_inertia, bool):
            raise ValueError(f"rotary_inertia: must be true or false, got {self.rotary_inertia!r}")

    # derived quantities in the internal unit system
    @property
    def E(self) -> float:  # MPa = N mm-2
        return self.youngs_modulus_gpa * 1e3

    @property
    def rho(self) -> float:  # t mm-3
        return self.density_kg_m3 * 1e-12

    @property
    def area(self) -> float:  # mm2
        return self.width * self.thickness

    @property
    def inertia(self) -> float:  # mm4
        return self.width * self.thickness**3 / 12.0

    @property
    def g(self) -> float:  # mm s-2
        return self.gravity_m_s2 * 1e3

    @property
    def weight(self) -> float:  # N
        return self.rho * self.area * self.length * self.g

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any]) -> BeamParams:
        return _from_mapping(cls, data, "beam.")


@dataclass(frozen=True)
class DiscParams:
    """Rigid disc rotating clockwise about its fixed centre (master surface).

    Exactly one of ``speed_rev_per_min`` / ``surface_speed_mm_s`` must be given: the paper states
    15.2 rev/min and claims it equals the 0.5 mm/s belt speed, which it does not for a 25 mm disc.
    """

    diameter: float = 25.0  #: disc diameter [mm]
    speed_rev_per_min: float | None = None  #: angular speed [rev/min]
    surface_speed_mm_s: float | None = None  #: surface (belt-equivalent) speed [mm s-1]
    #: turning direction seen with the clamp on the left: clockwise drives the disc top away from the
    #: clamp (the paper's "clockwise"; it does not say from which side it is seen)
    direction: str = "clockwise"

    def __post_init__(self) -> None:
        _positive("diameter", self.diameter)
        if self.direction not in DISC_DIRECTIONS:
            raise ValueError(f"direction: must be one of {DISC_DIRECTIONS}, got {self.direction!r}")
        given = [k for k in ("speed_rev_per_min", "surface_speed_mm_s") if getattr(self, k) is not None]
        if len(given) != 1:
            raise ValueError("speed_rev_per_min: give exactly one of speed_rev_per_min / surface_speed_mm_s")
        v = getattr(self, given[0])
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
            raise ValueError(f"{given[0]}: must be a finite number >= 0, got {v!r}")

    @property
    def surface_speed(self) -> float:
        """Disc surface speed at the contact [mm s-1]."""
        if self.surface_speed_mm_s is not None:
            return float(self.surface_speed_mm_s)
        return float(self.speed_rev_per_min) * 2.0 * math.pi / 60.0 * self.diameter / 2.0

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any]) -> DiscParams:
        return _from_mapping(cls, data, "disc.")


@dataclass(frozen=True)
class ContactParams:
    """Contact between the lower face of the beam's free end ("node 1") and the disc.

    Geometry: the beam axis stays horizontal; the disc is placed so that it touches the lower corner of
    the free end at a point whose outward disc normal is tilted by ``angle_deg`` from the vertical towards
    the clamp (angle 0: contact at the top of the disc, normal vertical). Disc rotation is clockwise, so
    the surface velocity at the contact is V (cos a, sin a): for a > 0 friction pushes the tip away from
    the clamp *and* upwards (off the disc); a < 0 pushes it into the disc (sprag side).
    """

    method: str = "kinematic"  #: "kinematic" (exact non-penetration), "penalty", "fixed_normal" (Sec. 10)
    angle_deg: float = 0.0  #: contact angle a [deg]
    penalty_stiffness: float = 1.0e3  #: penalty normal stiffness k_p [N mm-1] (method "penalty" only)
    #: contact at the lower face (h/2 below the axis, the paper's slave surface: friction then also
    #: bends the beam through the moment h/2*F_t) instead of on the beam axis (a control). Converges with
    #: the element count once the beam has rotary inertia (BeamParams.rotary_inertia).
    surface_offset: bool = True
    #: the paper's "node 1": where on the free end the displacement is measured
    output_node: str = "free_end_lower"

    def __post_init__(self) -> None:
        if self.method not in CONTACT_METHODS:
            raise ValueError(f"method: must be one of {CONTACT_METHODS}, got {self.method!r}")
        if not (isinstance(self.angle_deg, (int, float)) and -80.0 <= self.angle_deg <= 80.0):
            raise ValueError(f"angle_deg: must lie in [-80, 80] degrees, got {self.angle_deg!r}")
        _positive("penalty_stiffness", self.penalty_stiffness)
        if not isinstance(self.surface_offset, bool):
            raise ValueError(f"surface_offset: must be true or false, got {self.surface_offset!r}")
        if self.output_node not in OUTPUT_NODES:
            raise ValueError(f"output_node: must be one of {OUTPUT_NODES}, got {self.output_node!r}")

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any]) -> ContactParams:
        return _from_mapping(cls, data, "contact.")


@dataclass(frozen=True)
class SolverParams:
    """Explicit central-difference settings."""

    t_end: float = 1.0  #: simulated time [s] (the 1-DOF runs' name)
    safety_factor: float = 0.9  #: dt = safety_factor * 2 / omega_max [-]
    output_dt: float = 1.0e-5  #: sampling interval of the stored trajectory [s]
    initial_state: str = "static"  #: "static" (gravity equilibrium in contact) or "drop" (undeformed, g at 0)
    mass_damping: float = 0.0  #: mass-proportional Rayleigh damping alpha [s-1]
    stiffness_damping: float = 0.0  #: stiffness-proportional Rayleigh damping beta [s]

    def __post_init__(self) -> None:
        _positive("t_end", self.t_end)
        _positive("output_dt", self.output_dt)
        if not (0 < self.safety_factor <= 1.0):
            raise ValueError(f"safety_factor: must lie in (0, 1], got {self.safety_factor!r}")
        if self.initial_state not in INITIAL_STATES:
            raise ValueError(f"initial_state: must be one of {INITIAL_STATES}, got {self.initial_state!r}")
        if not (self.mass_damping >= 0):
            raise ValueError(f"mass_damping: must be >= 0, got {self.mass_damping!r}")
        if not (isinstance(self.stiffness_damping, (int, float)) and 0 <= self.stiffness_damping < 1e-3):
            raise ValueError(f"stiffness_damping: must lie in [0, 1e-3) s, got {self.stiffness_damping!r}")

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any]) -> SolverParams:
        return _from_mapping(cls, data, "solver.")


@dataclass(frozen=True)
class FrictionTable:
    """Tabulated mu(|v_r|) as fed to ABAQUS (Fig. 17 / Fig. 18): static limit mu(0), linear interpolation,
    constant extrapolation beyond the last speed."""

    speeds: tuple = field(default=(0.0, 0.6))  #: relative speeds |v_r| [mm s-1], ascending, from 0
    mu: tuple = field(default=(0.5, 0.4))  #: friction coefficients [-]

    def __post_init__(self) -> None:
        s = np.asarray(self.speeds, float)
        m = np.asarray(self.mu, float)
        if s.ndim != 1 or s.size < 1 or s.size != m.size:
            raise ValueError("speeds: speeds and mu must be 1-D of equal non-zero length")
        if s[0] != 0.0 or np.any(s < 0) or np.any(np.diff(s) <= 0):
            raise ValueError("speeds: must start at 0 and be strictly ascending")
        if np.any(~np.isfinite(m)) or np.any(m < 0):
            raise ValueError("mu: must be finite and >= 0")

    @property
    def static(self) -> float:
        return float(self.mu[0])

    def __call__(self, speed: float) -> float:
        return float(np.interp(abs(speed), self.speeds, self.mu))

    def slope(self, speed: float) -> float:
        """d mu / d|v_r| [s mm-1] at ``speed`` (right derivative on the table's linear pieces)."""
        s = np.asarray(self.speeds)
        if s.size < 2 or speed >= s[-1]:
            return 0.0
        i = int(np.searchsorted(s, abs(speed), side="right")) - 1
        return float((self.mu[i + 1] - self.mu[i]) / (s[i + 1] - s[i]))

    @classmethod
    def from_csv(cls, path) -> FrictionTable:
        data = np.genfromtxt(path, delimiter=",", names=True)
        names = data.dtype.names
        if names is None or "relative_velocity_mm_per_s" not in names or "mu" not in names:
            raise ValueError("speeds: CSV needs header relative_velocity_mm_per_s,mu")
        s = np.atleast_1d(data["relative_velocity_mm_per_s"]).astype(float)
        m = np.atleast_1d(data["mu"]).astype(float)
        order = np.argsort(s, kind="stable")
        s, m = s[order], m[order]
        keep = np.concatenate([[True], np.diff(s) > 0])  # drop duplicate speeds (keep first)
        s, m = s[keep], m[keep]
        if s[0] > 0:  # table not starting at 0: static limit taken as the first value (ABAQUS semantics)
            s, m = np.concatenate([[0.0], s]), np.concatenate([[m[0]], m])
        return cls(tuple(s.tolist()), tuple(m.tolist()))

    @classmethod
    def paper_fig17(cls) -> FrictionTable:
        """The Fig. 17 description: 0.5 at rest, falling linearly to 0.4 at 0.6 mm/s, then flat."""
        return cls((0.0, 0.6), (0.5, 0.4))

    @classmethod
    def linear(cls, mu0: float, slope: float, v_max: float = 1e3) -> FrictionTable:
        """mu = mu0 + slope*|v| clipped at >= 0, for stability cross-checks [slope in s mm-1]."""
        return cls((0.0, v_max), (mu0, max(mu0 + slope * v_max, 0.0)))
