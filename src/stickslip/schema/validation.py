"""The ``validation`` section (``config/validation.yaml``): the friction-law validation."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from .base import Open, Positive, Section, check_refs
from .methods import StudyMethod, Timing
from .onedof import BeltParameters, Law, check_run_lengths, merged_run_lengths


class Tolerance(Section):
    abs: Positive
    reason: Annotated[str, Field(pattern=r"\S", description="why this tolerance (not blank)")]


class ValidationTolerances(Section):
    time: Tolerance
    position: Tolerance
    closed_form: Tolerance


class SwitchSettings(Open):
    """Settings of the switch solver (others are checked by ``SwitchSolver`` at construction)."""

    rtol: Positive | None = None
    atol: Positive | None = None


class Peer(Section):
    program: str
    method: Literal["Adams", "BDF"]
    rtol: Positive
    atol: Positive


class ValidationLaw(Section):
    description: str | None = None
    law: Law
    params: BeltParameters | None = None
    closed_form: bool = Field(False, description="compare with the textbook Coulomb cycle too")


class RoundTrip(Section):
    extension_factor: Annotated[float, Field(gt=1, allow_inf_nan=False)]
    curved_law: Law
    bins: Annotated[list[Annotated[int, Field(ge=2)]], Field(min_length=1)]
    curved_solver: SwitchSettings | None = None


class LawTiming(Timing):
    max_rhs: Annotated[int, Field(ge=1)]
    max_cpu: Positive


class LawMethod(StudyMethod):
    #: the methods whose right-hand side is one sign equation, which any law fits, and the switch solver
    solver: Literal["sign_rk", "smooth", "switch"]


class MethodsPerLaw(Section):
    laws: list[str]
    t_end: Positive
    output_dt: Positive
    timing: LawTiming
    methods: Annotated[list[LawMethod], Field(min_length=1)]
    paper_method: str

    @model_validator(mode="after")
    def lengths_fit(self):
        check_run_lengths(*merged_run_lengths([("validation.methods_per_law", self)]))
        return self


# A job reads part of the section (its params): each part is a model, the whole section all of them.
class LawRuns(Section):
    """What a job solving the configured laws reads: the scene, the laws, the reference solver."""

    base_params: BeltParameters
    solver: SwitchSettings
    laws: Annotated[dict[str, ValidationLaw], Field(min_length=1)]


class PeerJob(LawRuns):
    """The peer comparison's part: every law against CVODE and the closed form."""

    t_end: Positive
    peer: Peer
    tolerances: ValidationTolerances


class LawMethodsJob(LawRuns):
    """The methods study on nonlinear laws' part."""

    methods_per_law: MethodsPerLaw

    @model_validator(mode="after")
    def laws_exist(self):
        refs = [("validation.methods_per_law.laws", name) for name in self.methods_per_law.laws]
        check_refs(refs, self.laws, "validation.laws")
        return self


class Validation(PeerJob, LawMethodsJob):
    round_trip: RoundTrip
