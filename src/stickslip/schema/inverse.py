"""The ``inverse`` section (``config/inverse.yaml``): the inverse study."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import Finite, Names, NonNegative, Positive, Section, Units, Variant, check_refs
from .onedof import Baseline, OnedofDefaults, Scene, Sweep

#: Parameters the inverse study may free, in its order (``stickslip.inverse.problem.PARAMS`` is this).
InverseParameter = Literal["sigma", "damping", "mu_s", "normal_force", "stiffness", "mass", "plateau_speed"]


class Range(Section):
    min: Positive
    max: Positive

    @model_validator(mode="after")
    def ordered(self):
        if not self.min < self.max:
            raise ValueError(f"need min < max, got {self.min!r}, {self.max!r}")
        return self


class Bound(Range):
    reason: Annotated[str, Field(min_length=1)]


class Family(Section):
    variant: Variant
    free: Annotated[list[InverseParameter], Field(min_length=1)]


class InverseFigure(Section):
    title: str | None = None
    scene: str | None = None
    sweep: str | None = None
    claims: Names

    @model_validator(mode="after")
    def scene_or_sweep(self):
        if (self.scene is None) == (self.sweep is None):
            raise ValueError("give exactly one of scene (an onedof scene) or sweep (an onedof sweep)")
        return self


class Hypothesis(Section):
    """Values applied to every run of the joint problem (every other parameter as stated)."""

    description: Annotated[str, Field(min_length=1)]
    sigma: NonNegative | None = None
    units: Units | None = None
    output_dt: Positive | None = None
    eq4_term: bool | None = None
    mu_k_ratio: Range | None = Field(None, description="mu_k / mu_s scanned over [min, max]")


class InverseSettings(Section):
    starts: Annotated[int, Field(ge=1)]
    max_nfev: Annotated[int, Field(ge=1)]
    walkers: Annotated[int, Field(ge=2)]
    steps: Annotated[int, Field(ge=1)]
    joint_steps: Annotated[int, Field(ge=0)] = Field(description="0: the joint region is the Laplace one")
    scan_points: Annotated[int, Field(ge=2)]
    loo: Literal["linear", "refit"]
    loo_nfev: Annotated[int, Field(ge=1)] | None = Field(None, description="default: max_nfev")
    corner: list[str] = []
    profile: list[str] | None = Field(
        None, description="figures whose fits get the profile likelihood (default: every figure)"
    )
    seed: int

    @property
    def refit_nfev(self) -> int:
        """Least-squares iterations of each leave-one-out refit."""
        return self.max_nfev if self.loo_nfev is None else self.loo_nfev


class Inverse(Section):
    long: bool = False
    claims_glob: str
    families: Annotated[dict[str, Family], Field(min_length=1)]
    stated: dict[str, Finite] | None = None
    bounds: dict[InverseParameter, Bound]
    constraints: dict[str, str] | None = None
    figures: Annotated[dict[str, InverseFigure], Field(min_length=1)]
    joint: Names
    hypotheses: dict[str, Hypothesis] = {}
    settings: dict[Literal["default", "long"], InverseSettings]

    @property
    def mode(self) -> Literal["default", "long"]:
        """The settings in use (``long``: longer chains, exact leave-one-out refits)."""
        return "long" if self.long else "default"

    @property
    def mode_settings(self) -> InverseSettings:
        return self.settings[self.mode]

    @property
    def settings_record(self) -> dict:
        """The settings in use as configured (a value left to its default is not listed) and the mode: what
        the results record and the notebook shows."""
        return {**self.mode_settings.model_dump(exclude_unset=True), "mode": self.mode}

    @model_validator(mode="after")
    def complete_and_consistent(self):
        missing = [p for p in InverseParameter.__args__ if p not in self.bounds]
        if missing:
            raise ValueError(f"bounds.{missing[0]}: missing (every parameter a family may free needs bounds)")
        for mode in ("default", "long"):
            if mode not in self.settings:
                raise ValueError(f"settings.{mode}: missing")
            corner = [(f"inverse.settings.{mode}.corner", f) for f in self.settings[mode].corner]
            check_refs([c for c in corner if c[1] != "joint"], self.figures, "inverse.figures")
            profiled = [(f"inverse.settings.{mode}.profile", f) for f in self.settings[mode].profile or []]
            check_refs(profiled, self.figures, "inverse.figures")
        check_refs([("inverse.joint", f) for f in self.joint], self.figures, "inverse.figures")
        return self


class InverseOnedof(Section):
    """The part of the ``onedof`` section the inverse study reads (its job's params): the baseline, the
    defaults, and the scenes and sweeps its claims and figures name. A part: the whole section was checked
    at parse time (``Onedof``)."""

    baseline: Baseline
    defaults: OnedofDefaults
    scenes: dict[str, Scene]
    sweeps: dict[str, Sweep] = {}


class InverseJob(Section):
    """The inverse study's params: its section and its part of the 1-DOF one."""

    onedof: InverseOnedof
    inverse: Inverse
