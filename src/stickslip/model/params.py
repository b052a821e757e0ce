"""Parameters of the mass-on-moving-belt scene (paper Section 2-7, Fig. 1), and the one way every parameter
set of the package is checked.

All lengths are in mm and times in s, as the paper states them. The paper's units are not mutually
consistent (M in kg, K in N/mm, C in "N.mm/sec", N in N); see :func:`effective_mass` for the two
readings this project supports.

Checking: a parameter set declares each value's type and bound once, as a field annotated with the number
types below, and pydantic checks them when the object is built (:func:`parameter_set` for dataclasses,
``stickslip.fe.params.Params`` for models). A refused value raises ``ParameterError`` whose message starts
with its key. The config's typed sections are generated from the same fields (``stickslip.schema``), so the
config check and the object refuse the same values.
"""

from __future__ import annotations

import functools
import inspect
import math
from dataclasses import asdict, fields, replace
from typing import Annotated, Literal, get_args

from pydantic import ConfigDict, Field, TypeAdapter, ValidationError
from pydantic.dataclasses import dataclass as pydantic_dataclass

#: How the paper's numbers are read. ``as_given``: every number is used as printed in one equation,
#: as if the units were consistent (this is what reproduces the reported sub-hertz frequencies).
#: ``si``: M [kg] is converted so that forces are in N and lengths in mm (mass coefficient M*1e-3
#: N s^2/mm, C read as N s/mm), which puts the natural frequency at ~11 Hz.
Units = Literal["as_given", "si"]
UNIT_READINGS = get_args(Units)

Finite = Annotated[float, Field(allow_inf_nan=False)]
Positive = Annotated[float, Field(gt=0, allow_inf_nan=False)]
NonNegative = Annotated[float, Field(ge=0, allow_inf_nan=False)]
#: > 0, +inf allowed (no limit)
PositiveOrInf = Annotated[float, Field(gt=0)]
#: in (0, 1]
Fraction = Annotated[float, Field(gt=0, le=1, allow_inf_nan=False)]
#: a whole number >= 1
Count = Annotated[int, Field(ge=1)]

#: Unknown keys are errors, and YAML's types are meant: no "5" for 5, no bool for a number (an int is a
#: float); numbers are stored as floats.
STRICT = ConfigDict(extra="forbid", strict=True)


class ParameterError(ValueError):
    """A parameter is missing, non-finite or non-physical. The message names the key."""


def error_message(exc: ValidationError, positional: tuple[str, ...] = (), key: str | None = None) -> str:
    """The first error of ``exc`` as ``"<key>: <what is wrong>, got <value>"`` (``positional``: the field
    names of positional arguments, which pydantic locates by index; ``key``: the name of a lone value)."""
    err = exc.errors()[0]
    loc = [key] if key is not None else list(err["loc"])
    if loc and isinstance(loc[0], int) and loc[0] < len(positional):
        loc[0] = positional[loc[0]]
    key = ".".join(str(k) for k in loc)
    if "error" in err.get("ctx", {}):  # a check of the object's own: its message names the key
        return str(err["ctx"]["error"])
    kind = err["type"]
    if kind in ("extra_forbidden", "unexpected_keyword_argument"):
        return f"{key}: unknown key"
    if kind in ("missing", "missing_argument"):
        return f"{key}: required parameter is missing"
    if kind == "literal_error":
        return f"{key}: {err['input']!r} is not one of {err['ctx']['expected']}"
    return f"{key}: {err['msg'][0].lower()}{err['msg'][1:]}, got {err['input']!r}"


def parameter_set(cls=None, /, *, frozen: bool = True, **config):
    """Make ``cls`` a pydantic dataclass checked as STRICT (``config`` adds settings), whose bad values raise
    ParameterError naming the key; ``__post_init__`` holds the checks across fields."""
    if cls is None:
        return functools.partial(parameter_set, frozen=frozen, **config)
    cls = pydantic_dataclass(cls, frozen=frozen, config=ConfigDict(**STRICT, **config))
    validated_init = cls.__init__
    positional = tuple(f.name for f in fields(cls) if f.init)

    @functools.wraps(validated_init)
    def __init__(self, *args, **kwargs):
        try:
            validated_init(self, *args, **kwargs)
        except ValidationError as exc:
            raise ParameterError(error_message(exc, positional)) from None

    cls.__init__ = __init__
    return cls


def checked_arguments(**types):
    """Decorate a function so that each named argument is checked against its type (the number types above,
    a ``Literal``) by pydantic, strictly, when the function is called, and a refused one raises
    ParameterError naming it. The values are passed on as given; the checks across arguments stay in the
    function."""
    adapters = {name: TypeAdapter(kind) for name, kind in types.items()}

    def decorate(function):
        signature = inspect.signature(function)

        @functools.wraps(function)
        def checked(*args, **kwargs):
            given = signature.bind(*args, **kwargs).arguments
            for name, adapter in adapters.items():
                if name in given:
                    try:
                        adapter.validate_python(given[name], strict=True)
                    except ValidationError as exc:
                        raise ParameterError(error_message(exc, key=name)) from None
            return function(*args, **kwargs)

        return checked

    return decorate


@parameter_set
class BeltParams:
    """Mass on a moving belt, the paper's 1-DOF stick-slip model."""

    mass: Positive = Field(description="M, mass [kg] (paper: 1 kg).")
    stiffness: Positive = Field(description="K, spring stiffness [N/mm] (paper: 5 N/mm).")
    damping: NonNegative = Field(description='C, viscous damping [N s/mm] (paper prints "N.mm/sec"; 1.5).')
    mu_s: Positive = Field(description="Static friction coefficient [1] (paper: 0.5).")
    sigma: NonNegative = Field(
        description="Friction slope versus relative velocity [s/mm] (paper text 0.3, captions 0.5)."
    )
    normal_force: Positive = Field(description="N, normal load [N] (paper: 10 N).")
    x0: Finite = Field(0.0, description="Initial displacement [mm].")
    v0: Finite = Field(0.5, description="Initial velocity [mm/s].")
    belt_velocity: NonNegative = Field(0.5, description="Belt velocity V_b at t = 0 [mm/s].")
    belt_deceleration: NonNegative = Field(
        0.0, description="Belt deceleration [mm/s^2]; the belt speed is max(V_b - d t, 0) (Section 6: 0.025)."
    )
    units: Units = Field("as_given", description="Unit reading, one of UNIT_READINGS.")
    plateau_speed: PositiveOrInf = Field(
        math.inf,
        description="Relative speed [mm/s] beyond which the friction coefficient stays constant (Fig. 17's "
        "text: it levels off at 0.6 mm/s); inf = the printed law, falling linearly without bound.",
    )

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
