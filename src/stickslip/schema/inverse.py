"""The ``inverse`` section (``config/inverse.yaml``): the inverse study."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import Finite, Names, NonNegative, Positive, Section, Units, Variant, check_refs

#: Parameters the inverse study may free (``stickslip.inverse.problem.PARAMS``; a test keeps them equal).
InverseParameter = Literal["sigma", "damping", "mu_s", "normal_force", "stiffness", "mass", "plateau_speed"]


class Bound(Section):
    min: Positive
    max: Positive
    reason: Annotated[str, Field(min_length=1)]

    @model_validator(mode="after")
    def ordered(self):
        if not self.min < self.max:
            raise ValueError(f"need min < max, got {self.min!r}, {self.max!r}")
        return self


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


class MuKRatio(Section):
    min: Positive
    max: Positive

    @model_validator(mode="after")
    def ordered(self):
        if not self.min < self.max:
            raise ValueError(f"need min < max, got {self.min!r}, {self.max!r}")
        return self


class Hypothesis(Section):
    """Values applied to every run of the joint problem (every other parameter as stated)."""

    description: Annotated[str, Field(min_length=1)]
    sigma: NonNegative | None = None
    units: Units | None = None
    output_dt: Positive | None = None
    eq4_term: bool | None = None
    mu_k_ratio: MuKRatio | None = None


class InverseSettings(Section):
    starts: Annotated[int, Field(ge=1)]
    max_nfev: Annotated[int, Field(ge=1)]
    walkers: Annotated[int, Field(ge=2)]
    steps: Annotated[int, Field(ge=1)]
    joint_steps: Annotated[int, Field(ge=0)] = Field(description="0: the joint region is the Laplace one")
    scan_points: Annotated[int, Field(ge=2)]
    loo: Literal["linear", "refit"]
    loo_nfev: Annotated[int, Field(ge=1)] | None = None
    corner: list[str] = []
    profile: list[str] | None = Field(
        None, description="figures whose fits get the profile likelihood (default: every figure)"
    )
    seed: int


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
