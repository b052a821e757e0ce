"""The ``methods_study`` section (``config/methods.yaml``): the solver-methods study."""

from __future__ import annotations

import itertools
from typing import Annotated, Any, Literal

from pydantic import Field, field_validator, model_validator

from .base import Finite, NonNegative, Positive, Section, Variant, belt_parameter, check_refs
from .onedof import BeltParameters, check_run_lengths, merged_run_lengths


class StudyMethod(Section):
    solver: Literal["exact", "sign_rk", "smooth", "karnopp", "moreau", "switch"]
    settings: dict[str, Any] | None = None
    sweep: dict[str, Annotated[list[Any], Field(min_length=1)]] | None = None
    atol_per_rtol: Positive | None = Field(None, description="atol = rtol x this, for every swept rtol")

    @model_validator(mode="after")
    def atol_follows_an_rtol(self):
        if self.atol_per_rtol is not None and "rtol" not in {**(self.settings or {}), **(self.sweep or {})}:
            raise ValueError("atol_per_rtol: needs an rtol in settings or sweep")
        return self

    def combinations(self) -> list[dict]:
        """The settings of each run: the fixed settings with one value of every swept key (the product,
        in the order written)."""
        sweep = self.sweep or {}
        out = []
        for combo in itertools.product(*sweep.values()):
            settings = {**(self.settings or {}), **dict(zip(sweep, combo))}
            if self.atol_per_rtol is not None:
                settings["atol"] = settings["rtol"] * self.atol_per_rtol
            out.append(settings)
        return out


class Budget(Section):
    max_rhs: Annotated[int, Field(ge=1)]
    max_cpu: Positive


class Timing(Section):
    min_repeats: Annotated[int, Field(ge=1)]
    max_repeats: Annotated[int, Field(ge=1)]
    min_total_cpu: NonNegative
    slow_run: Positive = 1.0
    """A run taking longer than this [s of CPU] is timed once."""

    @model_validator(mode="after")
    def ordered(self):
        if self.min_repeats > self.max_repeats:
            raise ValueError(f"min_repeats {self.min_repeats!r} > max_repeats {self.max_repeats!r}")
        return self


class StudyScene(Section):
    variant: Variant
    params: BeltParameters | None = None


class FailureMap(Section):
    scene: str
    parameter: str
    values: Annotated[list[Finite], Field(min_length=1)]
    t_end: Positive
    methods: Annotated[list[StudyMethod], Field(min_length=1)]

    _parameter = field_validator("parameter")(belt_parameter)


class MethodsStudy(Section):
    base_params: BeltParameters
    t_end: Positive
    output_dt: Positive
    budget: Budget
    timing: Timing
    paper_method: StudyMethod
    scenes: Annotated[dict[str, StudyScene], Field(min_length=1)]
    methods: Annotated[list[StudyMethod], Field(min_length=1)]
    failure_map: FailureMap

    @model_validator(mode="after")
    def lengths_fit(self):
        check_run_lengths(*merged_run_lengths([("methods_study", self)]))
        return self

    @model_validator(mode="after")
    def failure_map_scene_exists(self):
        check_refs([("failure_map.scene", self.failure_map.scene)], self.scenes, "methods_study.scenes")
        return self
