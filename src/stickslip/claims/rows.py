"""One claims row as a typed record: every key checked when the claims files are read, before any job.

A row that a typo would silently change (``tolerence`` for ``tolerance`` would make the band 0, a negative
tolerance turns equal numbers into a deviation, ``value: "1.5 mm"`` fails inside the table job) is an error
naming its file, claim id and key. What a row may hold depends on its kind:

==========  ======================================================  ==========================
kind        needs                                                    may not hold
==========  ======================================================  ==========================
value       dataset, variable, value, unit, tolerance               lhs, rhs, relation, coord, sign
ratio       lhs, rhs, value, tolerance                               dataset, relation, coord, sign
compare     lhs, rhs, relation                                       value, tolerance, coord, sign
trend       dataset, variable, coord, sign                           lhs, rhs, value, tolerance, relation
==========  ======================================================  ==========================
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from ..catalogue import fe_model_of
from ..schema.base import Finite, NonNegative

STATUSES = ("reproduced", "deviates", "indistinguishable", "not-comparable")

#: What a claim row can show, declared on every row (``evidence``) and checked here. Only ``evidence`` rows
#: count toward a figure's verdict and the page's totals; the others are listed apart with their class.
EVIDENCE_CLASSES = {
    "evidence": "the run could have gone either way: the row tests the paper",
    "by_construction": "the stated setup admits one outcome (an input, a definition, or mechanics that fix "
    "it): the row cannot fail, so it proves nothing",
    "relabel": "reads the paper's words in a way its own text contradicts",
    "fit": "checks a setup fitted to the paper's numbers, not the stated one",
    "model_check": "checks this project's model against an established code or a closed form, not a number "
    "the paper reports: it can fail, but its outcome says nothing of the paper",
}
Evidence = Literal["evidence", "by_construction", "relabel", "fit", "model_check"]
Status = Literal["reproduced", "deviates", "indistinguishable", "not-comparable"]

#: The models a beam-on-disc row (one reading a dataset under ``results/fe/``) can be decided by, declared on
#: every such row (``model``). The claims table decides a ``beam`` row only where the model comparison
#: (results/fe/model_comparison.csv) finds beam and continuum agreeing for its scene and quantity
#: (stickslip.claims.models).
MODELS = {
    "beam": "frame elements with rotary inertia (results/fe/<reading>/, the sweeps, studies and fits)",
    "continuum": "the 100 x 1 plane-stress strip, the paper's own kind of model (results/fe/continuum*)",
    "reduced": "the Craig-Bampton reduced beam",
    "closed_form": "a formula of the stated inputs (a unit conversion, a stable-step count): no simulation",
    "peer": "the continuum strip beside CalculiX, an established FE code, on the strip's linear states",
}
Model = Literal["beam", "continuum", "reduced", "closed_form", "peer"]

#: The paper's numbered figures (Figure 1 to Figure 36); a claim's ``figures`` name some of them.
PAPER_FIGURES = range(1, 37)

Text = Annotated[str, Field(min_length=1)]
#: A per-reading value: one for every reading, or ``{default: ..., <reading>: ...}``.
PerReading = Text | dict[str, Text]

NEEDS = {
    "value": ("dataset", "variable", "value", "unit", "tolerance"),
    "ratio": ("lhs", "rhs", "value", "tolerance"),
    "compare": ("lhs", "rhs", "relation"),
    "trend": ("dataset", "variable", "coord", "sign"),
}
MAY_NOT = {
    "value": ("lhs", "rhs", "relation", "coord", "sign"),
    "ratio": ("dataset", "variable", "relation", "coord", "sign"),
    "compare": ("value", "tolerance", "coord", "sign"),
    "trend": ("lhs", "rhs", "value", "tolerance", "relation"),
}


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, frozen=True)


class Tolerance(_Strict):
    """Half-width of the accepted band around the reported number: the larger of ``rel`` x |value| and
    ``abs``, and why that width."""

    # at most 100 %: a wider band accepts any number of the value's sign and zero (the claims use <= 25 %)
    rel: Annotated[float, Field(ge=0, le=1, allow_inf_nan=False)] | None = None
    abs: NonNegative | None = None
    reason: Text

    @model_validator(mode="after")
    def _has_width(self):
        if self.rel is None and self.abs is None:
            raise ValueError("needs rel or abs (a band of width 0 is never what a reported number means)")
        return self


class Operand(_Strict):
    """One side of a ratio or comparison: a dataset's scalar, or a constant."""

    dataset: Text | None = None
    variable: Text | None = None
    value: Finite | None = None

    @model_validator(mode="after")
    def _one_source(self):
        if self.value is None and (self.dataset is None or self.variable is None):
            raise ValueError("needs dataset and variable, or a value")
        if self.value is not None and (self.dataset is not None or self.variable is not None):
            raise ValueError("a constant (value) cannot also name a dataset or variable")
        return self


class ClaimRow(_Strict):
    id: Annotated[str, Field(pattern=r"^[a-z0-9_]+$")]
    section: Text
    figure: Text = Field(description="display label, e.g. 'Fig. 21 vs Fig. 23'")
    figures: list[int] = Field(description="the paper figures the claim is about ([] for text-only claims)")
    quote: Text
    kind: Literal["value", "ratio", "compare", "trend"]
    expected: Status | dict[str, Status]
    dataset: Text | None = None
    variable: Text | None = None
    note: PerReading | None = None
    value: Finite | None = None
    unit: str | None = None
    tolerance: Tolerance | None = None
    lhs: Operand | None = None
    rhs: Operand | None = None
    relation: Literal[">", "<", ">=", "<="] | None = None
    coord: Text | None = None
    sign: Literal[-1, 0, 1] | None = None
    comparable: bool | None = None
    evidence: Evidence = Field(description="what the row can show (EVIDENCE_CLASSES)")
    evidence_note: Text | None = Field(
        None, description="why the row is not evidence (required for every class but `evidence`)"
    )
    twin: Annotated[str, Field(pattern=r"^[a-z0-9_]+$")] | None = Field(
        None, description="the row that decides the same sentence at the other disc speed (beam on disc)"
    )
    one_speed: Text | None = Field(
        None, description="why a beam-on-disc row is decided at one disc speed only (no twin)"
    )
    coord_scale: Literal["log"] | None = None
    min_relative_change: NonNegative | None = None
    model: Model | None = Field(None, description="the model that decides a beam-on-disc row (MODELS)")
    invariance: dict[str, Text] | None = Field(
        None,
        description="per reading: an exact invariance of that reading's model that makes a comparison's two "
        "sides equal, and the test that shows it; sides equal within the noise then decide the row (a strict "
        "relation fails)",
    )

    def dataset_refs(self) -> list[tuple[str, ClaimRow | Operand]]:
        """(key, row or operand) of every dataset the row reads, its subject (``dataset`` or ``lhs``) first;
        the key is the one an error names (``dataset``, ``lhs.dataset``, ``rhs.dataset``)."""
        sides = [("dataset", self), ("lhs.dataset", self.lhs), ("rhs.dataset", self.rhs)]
        return [(key, ref) for key, ref in sides if ref is not None and ref.dataset is not None]

    def dataset_paths(self) -> list[str]:
        """Every dataset the row reads, its subject (``dataset`` or ``lhs``) first."""
        return [ref.dataset for _, ref in self.dataset_refs()]

    @model_validator(mode="after")
    def _fits_its_kind(self):
        missing = [k for k in NEEDS[self.kind] if getattr(self, k) is None]
        if missing:
            raise ValueError(f"{missing[0]}: a {self.kind} claim needs it")
        extra = [k for k in MAY_NOT[self.kind] if getattr(self, k) is not None]
        if extra:
            raise ValueError(f"{extra[0]}: not used by a {self.kind} claim (misplaced or misspelt key?)")
        if self.kind == "compare" and self.lhs.value is not None:
            raise ValueError("lhs: a comparison measures its left side (a dataset variable)")
        if self.invariance is not None and self.kind != "compare":
            raise ValueError("invariance: only a comparison's two sides can be equal by an invariance")
        if self.min_relative_change is not None and self.kind != "trend":
            raise ValueError("min_relative_change: only a trend claim has a floor")
        if self.twin is not None and self.one_speed is not None:
            raise ValueError("one_speed: a row with a twin at the other speed is decided at both")
        if self.evidence != "evidence" and self.evidence_note is None:
            raise ValueError(f"evidence_note: a {self.evidence} row says why it is not evidence")
        if self.evidence == "evidence" and self.evidence_note is not None:
            raise ValueError("evidence_note: only a row that is not evidence carries one")
        paths = self.dataset_paths()
        fe = any(fe_model_of(p) is not None for p in paths)
        if fe and self.model is None:
            raise ValueError("model: a beam-on-disc row (a dataset of the FE scenes) names its model")
        if not fe and self.model is not None:
            raise ValueError("model: only a beam-on-disc row (a dataset of the FE scenes) names one")
        if self.model in ("beam", "continuum") and (fe_model_of(paths[0]) == "continuum") != (
            self.model == "continuum"
        ):
            raise ValueError(f"model: a {self.model} row's subject dataset is {paths[0]}")
        bad = [f for f in self.figures if f not in PAPER_FIGURES]
        if bad:
            raise ValueError(f"figures: {bad[0]} is not a figure of the paper (1-{PAPER_FIGURES[-1]})")
        if len(set(self.figures)) != len(self.figures):
            raise ValueError("figures: a figure is listed twice")
        return self


class Claim(ClaimRow):
    """A row as the claims files hand it on (stickslip.claims.load.load_claims): the checked row, the file it
    came from (for error messages), and what the model comparison says about it once read
    (stickslip.claims.models.annotate). Never read from a claims file itself: the loader checks the file's
    row as a ``ClaimRow`` (so ``file`` there is an unknown key) and adds ``file`` after."""

    file: str = ""
    #: why the beam may not decide this row ("" when it may): the row is then not comparable
    not_adequate: str = ""
    #: both models' values at dt and dt/2 over the row's window, cited in its reason ("" when none)
    model_values: str = ""
