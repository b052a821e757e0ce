"""Friction laws beyond the affine one: typed, validated objects the switch-model solver accepts.

Every law here is a friction *coefficient* of the relative speed, with the force on the mass opposing the
relative velocity (the physically consistent sign of ``friction.py``):

    slip  (v_r != 0):  F = -N mu(|v_r|) sgn(v_r)
    stick (v_r == 0):  F in [-N mu_static, +N mu_static]   (set-valued; the equation of motion picks it)

``mu`` is the slip law, ``static`` its static limit. A law may jump at v_r = 0 (mu(0+) < mu_static: the
classical static/kinetic difference) but never above it: mu(0+) <= mu_static is checked, because otherwise a
mass released from stick would be pushed back into it (no consistent motion). Each law also defines its slip
coefficient as a smooth function of a *signed* speed (``mu_continued``) a little way below zero, so a
high-order integrator stepping across v_r = 0 inside one slip phase sees a smooth right-hand side.

Kinds (``kind`` in config):

``affine``     mu_s (1 - sigma min(|v_r|, v_p)): today's ``consistent`` variant (with optional plateau)
``coulomb``    mu_k in slip, mu_s at rest, mu_s >= mu_k (static/kinetic jump)
``stribeck``   mu_k + (mu_s - mu_k) exp(-|v_r| / v_s)
``rational``   mu_k + (mu_s - mu_k) / (1 + delta |v_r|)   (mu_k = 0: the mu_s/(1 + delta|v_r|) law)
``tabulated``  monotone (PCHIP) interpolation of a mu(|v_r|) table read from CSV or netCDF (Fig. 17's table);
               held constant beyond its last speed, as ABAQUS and ``np.interp`` do

The printed-sign variants of ``friction.py`` (``eq3_printed``, ``eq4_printed``) are not friction laws in this
sense: their force pushes the mass *away* from the belt velocity, v_r = 0 repels, and they never stick. They
stay with the exact solver (``solvers/exact.py``); ``law_from_reading`` refuses them with that reason.
"""

from __future__ import annotations

import bisect
import csv
import math
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

from .params import BeltParams, NonNegative, ParameterError, Positive, PositiveOrInf, parameter_set


class FrictionLaw:
    """Common interface: ``mu(v_r)`` in slip, ``static`` at rest, ``force(v_r, N)``, ``breakpoints``."""

    kind: ClassVar[str] = ""

    def __post_init__(self):
        if getattr(self, "mu_k", 0.0) > self.mu_s:
            raise ParameterError(f"mu_k: must be <= mu_s = {self.mu_s!r}, got {self.mu_k!r}")

    @property
    def static(self) -> float:
        """The static limit mu_static (mu_s unless a law says otherwise)."""
        return self.mu_s

    def mu_continued(self, speed):
        """Slip coefficient at a signed speed (the law's own formula, continued a little below 0)."""
        raise NotImplementedError  # pragma: no cover

    @property
    def breakpoints(self) -> tuple[float, ...]:
        """Relative speeds > 0 where mu is not smooth (the solver restarts its integration there)."""
        return ()

    def mu(self, relative_velocity):
        """Slip coefficient mu(|v_r|) [1] (at v_r = 0 the limit from slip, mu(0+))."""
        return self.mu_continued(np.abs(np.asarray(relative_velocity, dtype=float)))

    @property
    def kinetic_limit(self) -> float:
        """mu(0+): the coefficient just after the mass leaves stick."""
        return float(self.mu(0.0))

    def force(self, relative_velocity, normal_force: float):
        """Slip friction force on the mass [N], -N mu(|v_r|) sgn(v_r); 0 at v_r = 0 (set-valued there)."""
        vr = np.asarray(relative_velocity, dtype=float)
        return -normal_force * self.mu(vr) * np.sign(vr)

    def describe(self) -> dict:
        """Config mapping of the law (what the dataset attributes record)."""
        return {"kind": self.kind, **{f.name: getattr(self, f.name) for f in fields(self) if f.repr}}


@parameter_set
class AffineLaw(FrictionLaw):
    """mu_s (1 - sigma min(|v_r|, v_p)): the affine ``consistent`` variant, optionally levelling off."""

    mu_s: Positive
    sigma: NonNegative
    plateau_speed: PositiveOrInf = math.inf
    kind: ClassVar[str] = "affine"

    def mu_continued(self, speed):
        return self.mu_s * (1.0 - self.sigma * np.minimum(speed, self.plateau_speed))

    @property
    def breakpoints(self) -> tuple[float, ...]:
        return (self.plateau_speed,) if math.isfinite(self.plateau_speed) else ()


@parameter_set
class CoulombLaw(FrictionLaw):
    """Static/kinetic jump: mu_k while slipping, up to mu_s while sticking (mu_s >= mu_k > 0)."""

    mu_s: Positive
    mu_k: Positive
    kind: ClassVar[str] = "coulomb"

    def mu_continued(self, speed):
        return self.mu_k + 0.0 * np.asarray(speed, dtype=float)


@parameter_set
class StribeckLaw(FrictionLaw):
    """mu_k + (mu_s - mu_k) exp(-|v_r| / v_s): continuous at v_r = 0+, falling to mu_k."""

    mu_s: Positive
    mu_k: NonNegative
    v_s: Positive
    kind: ClassVar[str] = "stribeck"

    def mu_continued(self, speed):
        # the continuation below 0 is only ever needed near 0: bounded far out so a diverging trial step
        # of an integrator cannot overflow
        speed = np.maximum(np.asarray(speed, dtype=float), -20.0 * self.v_s)
        return self.mu_k + (self.mu_s - self.mu_k) * np.exp(-speed / self.v_s)


@parameter_set
class RationalLaw(FrictionLaw):
    """mu_k + (mu_s - mu_k) / (1 + delta |v_r|); with mu_k = 0 the mu_s / (1 + delta |v_r|) law."""

    mu_s: Positive
    delta: NonNegative
    mu_k: NonNegative = 0.0
    kind: ClassVar[str] = "rational"

    def mu_continued(self, speed):
        return self.mu_k + (self.mu_s - self.mu_k) / (1.0 + self.delta * np.asarray(speed, dtype=float))


@parameter_set(arbitrary_types_allowed=True)
class TabulatedLaw(FrictionLaw):
    """mu(|v_r|) from a table (speeds from 0, strictly increasing): PCHIP between rows, held beyond the last.

    PCHIP keeps the table's monotonicity (no overshoot between rows) and is continuously differentiable,
    so a slip phase needs no restarts at the rows. The static limit is the first row's value (mu at rest),
    unless ``static_mu`` is given.
    """

    speed: Any = field(repr=False)  # array-like: checked as a table below
    values: Any = field(repr=False)
    static_mu: Positive | None = None
    source: str = ""
    kind: ClassVar[str] = "tabulated"

    def __post_init__(self):
        speed = np.asarray(self.speed, dtype=float).ravel()
        values = np.asarray(self.values, dtype=float).ravel()
        if speed.shape != values.shape or speed.size < 2:
            raise ParameterError(f"table: need >= 2 rows of (speed, mu), got {speed.size} and {values.size}")
        if not (np.all(np.isfinite(speed)) and np.all(np.isfinite(values))):
            raise ParameterError("table: speeds and mu must be finite (NaN/inf found)")
        if speed[0] != 0.0:
            raise ParameterError(f"table: the first relative speed must be 0, got {float(speed[0])!r}")
        if np.any(np.diff(speed) <= 0):
            raise ParameterError("table: relative speeds must be strictly increasing")
        if np.any(values < 0):
            raise ParameterError("table: mu must be >= 0 (a magnitude |F|/N)")
        from scipy.interpolate import PchipInterpolator

        speed.flags.writeable = False
        values.flags.writeable = False
        object.__setattr__(self, "speed", speed)
        object.__setattr__(self, "values", values)
        interp = PchipInterpolator(speed, values, extrapolate=True)
        object.__setattr__(self, "_interp", interp)
        object.__setattr__(self, "_nodes", speed.tolist())
        object.__setattr__(self, "_coeffs", [tuple(float(c) for c in col) for col in interp.c.T])
        if self.kinetic_limit > self.static * (1 + 1e-12):
            raise ParameterError(
                f"{self.kind}: mu(0+) = {self.kinetic_limit!r} exceeds the static limit {self.static!r}"
            )

    @property
    def static(self) -> float:
        return float(self.values[0]) if self.static_mu is None else self.static_mu

    def mu_continued(self, speed):
        if isinstance(speed, float):  # the integrators' scalar calls: plain-float Horner, ~20x faster
            return self._scalar(speed)
        speed = np.asarray(speed, dtype=float)
        inside = self._interp(np.minimum(speed, self.speed[-1]))
        return np.where(speed >= self.speed[-1], self.values[-1], inside)

    def _scalar(self, speed: float) -> float:
        nodes, coeffs = self._nodes, self._coeffs
        if speed >= nodes[-1]:
            return float(self.values[-1])
        i = min(max(bisect.bisect_right(nodes, speed) - 1, 0), len(coeffs) - 1)
        c0, c1, c2, c3 = coeffs[i]
        h = speed - nodes[i]
        return ((c0 * h + c1) * h + c2) * h + c3

    def describe(self) -> dict:
        return {"kind": self.kind, "path": self.source, "rows": int(self.speed.size), "static": self.static}

    @classmethod
    def from_file(cls, path: str | Path, static_mu: float | None = None) -> TabulatedLaw:
        """Read a CSV (two columns: relative speed [mm/s], mu; one header line) or a netCDF (``mu`` over
        the ``relative_speed`` coordinate, as rule friction_table writes)."""
        path = Path(path)
        if not path.is_file():
            raise ParameterError(f"path: friction table {str(path)!r} does not exist")
        if path.suffix == ".nc":
            import xarray as xr

            with xr.open_dataset(path) as ds:
                if "mu" not in ds:
                    raise ParameterError(f"path: {str(path)!r} has no variable 'mu'")
                speed, values = ds["relative_speed"].values, ds["mu"].values
        else:
            with open(path, newline="") as fh:
                rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
            try:
                data = np.array([[float(a), float(b)] for a, b in rows[1:]])
            except ValueError as exc:
                raise ParameterError(f"path: {str(path)!r} is not a two-column numeric CSV: {exc}") from None
            speed, values = data[:, 0], data[:, 1]
        return cls(speed, values, static_mu=static_mu, source=str(path))


#: Config ``kind`` -> class.
LAW_KINDS: dict[str, type] = {
    cls.kind: cls for cls in (AffineLaw, CoulombLaw, StribeckLaw, RationalLaw, TabulatedLaw)
}
#: Config keys of each kind: its fields (a table is read from ``path``).
_LAW_KEYS = {kind: {f.name for f in fields(cls)} for kind, cls in LAW_KINDS.items()}
_LAW_KEYS["tabulated"] = {"path", "static_mu"}


def law_from_config(entry: dict, *, key: str = "law") -> FrictionLaw:
    """Build a law from a config mapping ``{kind: ..., <parameters>}``; errors name ``key.<field>``."""
    if not isinstance(entry, dict) or "kind" not in entry:
        raise ParameterError(f"{key}.kind: a law needs a kind, one of {sorted(LAW_KINDS)}")
    kind = entry["kind"]
    if kind not in LAW_KINDS:
        raise ParameterError(f"{key}.kind: {kind!r} is not one of {sorted(LAW_KINDS)}")
    values = {k: v for k, v in entry.items() if k != "kind"}
    unknown = sorted(set(values) - _LAW_KEYS[kind])
    if unknown:
        known = sorted(_LAW_KEYS[kind])
        raise ParameterError(f"{key}.{unknown[0]}: unknown parameter of a {kind} law (known: {known})")
    try:
        if kind == "tabulated":
            if "path" not in values:
                raise ParameterError("path: required parameter is missing")
            return TabulatedLaw.from_file(values["path"], values.get("static_mu"))
        return LAW_KINDS[kind](**values)
    except ParameterError as exc:
        raise ParameterError(f"{key}.{exc}") from None


def law_from_reading(params: BeltParams, variant: str) -> AffineLaw:
    """The affine law of the pipeline's ``consistent`` reading (mu_s, sigma, plateau from ``params``)."""
    if variant != "consistent":
        raise ParameterError(
            f"variant: {variant!r} pushes the mass away from the belt velocity (v_r = 0 repels, it never "
            "sticks) and is not a friction law with a static limit; only 'consistent' maps onto a law"
        )
    return AffineLaw(params.mu_s, params.sigma, params.plateau_speed)


@dataclass(frozen=True)
class LawModel:
    """The mass on the belt (``params``: M, K, C, N, belt, initial state) with any friction ``law``.

    The equation of motion is the paper's Eq. 1, M x'' + C x' + K x = F, with F from ``law``; the friction
    fields of ``params`` (mu_s, sigma, plateau_speed) are not used, the law carries its own.
    """

    params: BeltParams
    law: FrictionLaw

    @classmethod
    def from_belt_model(cls, model) -> LawModel:
        """The law model of a ``BeltModel`` (its variant must be ``consistent``)."""
        return cls(model.params, law_from_reading(model.params, model.variant))

    @property
    def mass(self) -> float:
        return self.params.effective_mass

    def belt_velocity(self, t):
        return self.params.belt_velocity_at(t)

    def acceleration(self, t, x, v, direction: int):
        """x'' during slip in ``direction`` (+1: v > V_b, -1: v < V_b), with the law continued smoothly."""
        p = self.params
        vb = p.belt_velocity if p.belt_deceleration == 0.0 else self.belt_velocity(t)
        vr = v - vb
        force = -p.normal_force * direction * self.law.mu_continued(direction * vr)
        return (force - p.damping * v - p.stiffness * x) / self.mass

    def stick_demand(self, t, x):
        """Force the friction must supply to carry the mass with the belt [N]: M a_b + C V_b + K x."""
        p = self.params
        return self.mass * p.belt_acceleration_at(t) + p.damping * self.belt_velocity(t) + p.stiffness * x

    @property
    def static_force(self) -> float:
        """N mu_static: the largest friction force stick can supply [N]."""
        return self.params.normal_force * self.law.static

    @property
    def slip_friction(self) -> SlipFriction:
        """The law at this model's normal force, as ``force(v, v_b)`` (what the metrics of a run read)."""
        return SlipFriction(self.law, self.params.normal_force)


@dataclass(frozen=True)
class SlipFriction:
    """A law's slip force as a function of mass and belt velocity, ``force(v, v_b)`` [N]: the interface of the
    readings' friction (``friction.py``) that ``analysis.friction_curve`` reads."""

    law: FrictionLaw
    normal_force: float

    def force(self, velocity, belt_velocity):
        vr = np.asarray(velocity, dtype=float) - np.asarray(belt_velocity, dtype=float)
        return self.law.force(vr, self.normal_force)
