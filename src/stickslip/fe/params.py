"""Frozen, validated parameter sets for the beam-on-rotating-disc scene (paper Sections 8-12).

Internal unit system (consistent): length mm, time s, force N, mass t (tonne = 1e3 kg), stress MPa.
Config values are given in engineering units (GPa, kg m-3, m s-2, rev/min, mm/s) and converted here.
Every validation error is a ``ValueError`` whose message starts with the offending key.

Each parameter set is a pydantic model: a key's type, bound and default are declared once, here; the
config's typed sections (stickslip.schema.fe) are generated from the same fields, so the two refuse the
same values naming the same key.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from ..model.params import (
    STRICT,
    Count,
    Fraction,
    NonNegative,
    ParameterError,
    Positive,
    checked_arguments,
    error_message,
)
from .mechanics import disc_surface_speed

INITIAL_STATES = ("static", "drop", "undeformed")  # "undeformed" = "drop" (kept for old configs)


#: a contact angle [deg] (the scenes' contact.angle_deg and the stability study's angles)
Angle = Annotated[float, Field(ge=-80, le=80, allow_inf_nan=False)]


class Params(BaseModel):
    """A parameter set: unknown keys are errors, YAML's types are meant (no "5" for 5, no bool for a number),
    and a refused value raises a ValueError that starts with its key."""

    model_config = ConfigDict(**STRICT, frozen=True)

    def __init__(self, **values: Any) -> None:
        try:
            super().__init__(**values)
        except ValidationError as exc:
            raise ParameterError(error_message(exc)) from None

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any]) -> Params:
        return cls(**data)


class BeamParams(Params):
    """Clamped-free elastic beam (pad back-plate), 2-D frame elements, 3 DOF/node (u, v, theta)."""

    length: Positive = Field(100.0, description="mm")  #: beam length L [mm]
    #: beam thickness h (in-plane, bending direction) [mm]
    thickness: Positive = Field(1.0, description="mm")
    #: out-of-plane width b [mm] (assumption: the paper gives none)
    width: Positive = Field(1.0, description="mm")
    youngs_modulus_gpa: Positive = 210.0  #: E [GPa] (steel back plate, assumption)
    density_kg_m3: Positive = 7850.0  #: rho [kg m-3] (steel, assumption)
    #: nu [-] (recorded only; Euler-Bernoulli elements do not use it)
    poisson_ratio: Annotated[float, Field(ge=0, lt=0.5, allow_inf_nan=False)] = 0.3
    gravity_m_s2: NonNegative = 9.81  #: g [m s-2], the only normal load
    n_elements: Count = 20  #: number of beam elements [-]
    #: "lumped" (HRZ diagonal, as explicit codes) or "consistent"
    mass: Literal["lumped", "consistent"] = "lumped"
    #: rotary inertia rho*I of the cross-sections (Rayleigh beam). Needed for contact at the lower face:
    #: without it the tangential inertia of the face point vanishes under mesh refinement.
    rotary_inertia: bool = True

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


class DiscParams(Params):
    """Rigid disc rotating clockwise about its fixed centre (master surface).

    Exactly one of ``speed_rev_per_min`` / ``surface_speed_mm_s`` must be given: the paper states
    15.2 rev/min and claims it equals the 0.5 mm/s belt speed, which it does not for a 25 mm disc.
    """

    diameter: Positive = Field(25.0, description="mm")  #: disc diameter [mm]
    speed_rev_per_min: NonNegative | None = None  #: angular speed [rev/min]
    surface_speed_mm_s: NonNegative | None = None  #: surface (belt-equivalent) speed [mm s-1]
    #: turning direction seen with the clamp on the left: clockwise drives the disc top away from the
    #: clamp (the paper's "clockwise"; it does not say from which side it is seen)
    direction: Literal["clockwise", "counterclockwise"] = "clockwise"

    @model_validator(mode="after")
    def one_speed(self):
        if (self.speed_rev_per_min is None) == (self.surface_speed_mm_s is None):
            raise ValueError("speed_rev_per_min: give exactly one of speed_rev_per_min / surface_speed_mm_s")
        return self

    @property
    def surface_speed(self) -> float:
        """Disc surface speed at the contact [mm s-1]."""
        if self.surface_speed_mm_s is not None:
            return float(self.surface_speed_mm_s)
        return disc_surface_speed(float(self.speed_rev_per_min), self.diameter)


class ContactParams(Params):
    """Contact between the lower face of the beam's free end ("node 1") and the disc.

    Geometry: the beam axis stays horizontal; the disc is placed so that it touches the lower corner of
    the free end at a point whose outward disc normal is tilted by ``angle_deg`` from the vertical towards
    the clamp (angle 0: contact at the top of the disc, normal vertical). Disc rotation is clockwise, so
    the surface velocity at the contact is V (cos a, sin a): for a > 0 friction pushes the tip away from
    the clamp *and* upwards (off the disc); a < 0 pushes it into the disc (sprag side).
    """

    #: "kinematic" (exact non-penetration), "penalty", "fixed_normal" (Sec. 10)
    method: Literal["kinematic", "penalty", "fixed_normal"] = "kinematic"
    angle_deg: Angle = 0.0  #: contact angle a [deg]
    #: penalty normal stiffness k_p [N mm-1] (method "penalty" only)
    penalty_stiffness: Positive = Field(1.0e3, description="N mm-1")
    #: contact at the lower face (h/2 below the axis, the paper's slave surface: friction then also
    #: bends the beam through the moment h/2*F_t) instead of on the beam axis (a control). Converges with
    #: the element count once the beam has rotary inertia (BeamParams.rotary_inertia).
    surface_offset: bool = True
    #: the paper's "node 1": where on the free end the displacement is measured
    output_node: Literal["free_end_lower", "free_end_axis", "free_end_upper"] = "free_end_lower"


#: dt = safety_factor * dt_crit: the one default of every explicit integrator and of the scenes' solver
DEFAULT_SAFETY_FACTOR = 0.9
#: how every explicit run starts unless told otherwise (config/fe.yaml's default too): undeformed, the load
#: applied at t = 0, as an ABAQUS/Explicit step starts
DEFAULT_INITIAL_STATE = "drop"


def initial_state_of(state: str | None) -> str:
    """An explicit run's start as every integrator and reader takes it: ``static`` or ``drop`` (its alias
    ``undeformed`` kept for old configs and datasets; None: ``DEFAULT_INITIAL_STATE``). ValueError names
    the key for anything else."""
    state = DEFAULT_INITIAL_STATE if state is None else state
    if state not in INITIAL_STATES:
        raise ValueError(f"initial_state: must be 'static' or 'drop', got {state!r}")
    return "drop" if state == "undeformed" else state


class SolverParams(Params):
    """Explicit central-difference settings."""

    #: simulated time [s] (the 1-DOF runs' name)
    t_end: Positive = Field(1.0, description="simulated time [s]")
    #: dt = safety_factor * 2 / omega_max [-]
    safety_factor: Fraction = DEFAULT_SAFETY_FACTOR
    #: sampling interval of the stored trajectory [s]
    output_dt: Positive = Field(1.0e-5, description="output interval [s]")
    #: "static" (gravity equilibrium in contact) or "drop" (undeformed, g at 0)
    initial_state: Literal[INITIAL_STATES] = DEFAULT_INITIAL_STATE
    #: mass-proportional Rayleigh damping alpha [s-1]
    mass_damping: NonNegative = Field(0.0, description="s-1")
    #: stiffness-proportional Rayleigh damping beta [s]; below 1e-3 s, far above any scene's (~1e-8 s)
    stiffness_damping: Annotated[float, Field(ge=0, lt=1e-3, allow_inf_nan=False)] = Field(
        0.0, description="s"
    )


#: the solver section's keys that an integrator takes under another name
RUN_ARGUMENTS = {"t_end": "duration", "output_dt": "output_interval"}


@checked_arguments(dt=Positive | None)
def run_settings(
    duration,
    safety_factor=DEFAULT_SAFETY_FACTOR,
    initial_state=DEFAULT_INITIAL_STATE,
    *,
    output_interval=None,
    dt=None,
    mass_damping=0.0,
    stiffness_damping=0.0,
) -> SolverParams:
    """An explicit run's settings as the solver section they are (``t_end`` = ``duration``), checked by its
    model before any work, so both integrators and the config refuse the same values naming the same key.
    ``output_interval`` None: every step; a given ``dt`` (> 0) replaces safety_factor * dt_crit."""
    given = {"output_dt": output_interval} if output_interval is not None else {}
    try:
        settings = SolverParams(
            t_end=duration,
            safety_factor=safety_factor,
            initial_state=DEFAULT_INITIAL_STATE if initial_state is None else initial_state,
            mass_damping=mass_damping,
            stiffness_damping=stiffness_damping,
            **given,
        )
    except ValueError as exc:  # named as the caller passed it
        key, _, why = str(exc).partition(":")
        raise ValueError(f"{RUN_ARGUMENTS.get(key, key)}:{why}") from None
    return settings.model_copy(update={"initial_state": initial_state_of(settings.initial_state)})


@dataclass(frozen=True)
class SceneParams:
    beam: BeamParams
    disc: DiscParams
    contact: ContactParams
    solver: SolverParams

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any]) -> SceneParams:
        """The parameters of a scene mapping: its beam, disc, contact and solver sections. Its other keys
        (output windows, description) are the studies'; which keys a scene may have is the config's typed
        model's to check (stickslip.schema.fe.FeScene), not listed again here."""
        return cls(
            BeamParams.from_mapping(data.get("beam", {})),
            DiscParams.from_mapping(data.get("disc", {"speed_rev_per_min": 15.2})),
            ContactParams.from_mapping(data.get("contact", {})),
            SolverParams.from_mapping(data.get("solver", {})),
        )


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
