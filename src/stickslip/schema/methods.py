"""The ``methods_study`` section (``config/methods.yaml``): the solver-methods study."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from .base import Finite, NonNegative, Positive, Section, Variant
from .onedof import BeltParameters, check_run_lengths, merged_run_lengths


class StudyMethod(Section):
    solver: Literal["exact", "sign_rk", "smooth", "karnopp", "moreau", "switch"]
    settings: dict[str, Any] | None = None
    sweep: dict[str, Annotated[list[Any], Field(min_length=1)]] | None = None
    atol_per_rtol: Positive | None = None


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
