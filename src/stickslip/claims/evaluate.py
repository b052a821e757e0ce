"""One claims row evaluated under one reading: the measurement, its status, and the reason a reader sees
(one conclusion sentence, the numbers, every caveat)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from .load import readings_of
from .measure import (
    MEASURE,
    Measurement,
    ModelAnswer,
    member_failures,
    model_answer,
    solver_failures,
    status_of,
)
from .rows import Claim


@dataclass
class ClaimResult:
    claim: str
    reading: str
    section: str
    figure: str
    kind: str
    quantity: str
    #: what the paper states: its number (value, ratio), or its words for a comparison ("a > b") or a trend
    #: ("increases"), never a model number
    reported: float | str
    unit: str
    measured: float
    #: a comparison's model number on the other side (its right-hand side); NaN for the other kinds
    reference: float
    deviation: float
    margin: float  #: distance of the decision variable to the claim's threshold
    spread: float  #: range of the decision variable across the perturbation ensemble (NaN: none)
    status: str
    expected: str
    matches_expected: bool
    #: what the row can show (stickslip.claims.rows.EVIDENCE_CLASSES); only ``evidence`` is counted
    evidence: str
    #: one conclusion sentence (at most CONCLUSION_LENGTH characters), then the numbers, then the caveats
    reason: str
    quote: str
    #: why a row is not comparable (NOT_COMPARABLE_CAUSES), or the model outcome that decided a row the
    #: run left unmeasured (ANSWER_CAUSES); '' for a row decided on its numbers
    cause: str = ""
    #: the model that decided a beam-on-disc row (stickslip.claims.rows.MODELS); '' for the 1-DOF rows
    model: str = ""


def _per_reading(value, reading, default=""):
    if isinstance(value, dict):
        return value.get(reading, value.get("default", default))
    return default if value is None else value


#: Longest conclusion sentence of a reason (what a reader scans before the numbers): room for the
#: one-sentence mechanism of a model answer.
CONCLUSION_LENGTH = 220

#: Why a row is not comparable, as the page counts them.
NOT_COMPARABLE_CAUSES = {
    "failure": "the solver run failed",
    "not_adequate": "no agreeing comparison with the continuum over the claim's window backs the beam here",
    "contradiction": "the paper contradicts this sentence elsewhere",
    "withheld": "the value moves under step halving, so it is withheld",
    "nothing": "nothing to measure in this run",
}
#: The model outcomes that decide a row the run left unmeasured (stickslip.analysis.outcome.ANSWERS).
ANSWER_CAUSES = {"diverged": "model diverges", "rest": "model at rest", "no_stick": "model never sticks"}


def not_comparable_cause(claim: Claim, m: Measurement, failures: list[str]) -> str:
    if failures:
        return "failure"
    if claim.not_adequate:
        return "not_adequate"
    if claim.comparable is False:
        return "contradiction"
    return "withheld" if m.withheld else "nothing"


def _short(text: str, limit: int) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 1].rstrip(" ,;:(") + "…"


def conclusion(
    claim: Claim,
    m: Measurement,
    status: str,
    failures: list[str],
    answer: ModelAnswer | None = None,
    reading: str = "",
) -> str:
    """One sentence that says what the row concludes, at most CONCLUSION_LENGTH characters: why first. A
    row decided by a model answer starts with the answer's mechanism; a value that deviates with a cause in
    the row's note (the paper contradicting itself, a reading precision) with that cause and the size."""
    kind = claim.kind
    if status == "not-comparable":
        text = f"Not comparable: {NOT_COMPARABLE_CAUSES[not_comparable_cause(claim, m, failures)]}."
    elif answer is not None and m.holds is None:
        verb = "Deviates" if status == "deviates" else "Undecided (the outcome moves within the noise)"
        text = f"{verb}, the model's answer: {answer.mechanism.rstrip('.')}."
    elif status == "indistinguishable":
        text = "Undecided: the margin to the threshold is within the run's own numerical noise."
    else:
        verb = "Reproduced" if status == "reproduced" else "Deviates"
        cause = _per_reading(claim.note, reading) if status == "deviates" else ""
        if kind in ("value", "ratio") and cause:  # the cause the paper's text gives first, then the size
            text = f"{verb} by {100 * m.deviation:+.0f} %: {cause.rstrip('.')}."
        elif kind in ("value", "ratio"):
            unit = "" if claim.unit in (None, "1") else f" {claim.unit}"
            text = (
                f"{verb}: {m.measured:.3g}{unit} against the paper's {float(m.reported):.3g}{unit} "
                f"({100 * m.deviation:+.0f} %)."
            )
        elif kind == "compare" and m.invariance:
            says = "holds" if m.holds else "does not hold"
            text = (
                f"{verb}: both sides are equal by an exact invariance of the model ({m.measured:.4g}), so "
                f"the paper's {m.quantity} {says}."
            )
        elif kind == "compare":
            says = "holds" if m.holds else "does not hold"
            text = f"{verb}: the paper's {m.quantity} {says} ({m.measured:.3g} vs {m.reference:.3g})."
        else:
            text = f"{verb}: the paper says {m.reported}; the run {'agrees' if m.holds else 'does not'}."
    if claim.evidence != "evidence":
        text = text[:-1] + f", {claim.evidence.replace('_', ' ')}."
    return _short(text, CONCLUSION_LENGTH)


def reason_text(
    claim: Claim, reading: str, m: Measurement, status: str, detail: str, failures, caveats, answer=None
):
    """The conclusion sentence, then the numbers, then every caveat: why the row is not evidence, values
    computed but withheld, failed sweep members, and the row's note (never dropped)."""
    parts = [conclusion(claim, m, status, failures, answer, reading), detail]
    if claim.evidence_note:
        parts.append(f"Not evidence ({claim.evidence.replace('_', ' ')}): {claim.evidence_note}")
    if m.withheld and not detail.startswith("withheld"):
        parts.append("withheld: " + "; ".join(m.withheld))
    parts += caveats
    note = _per_reading(claim.note, reading)
    parts.append(note)
    return " | ".join(" ".join(str(p).split()) for p in parts if p)


def evaluate(claim: Claim, reading: str, open_dataset: Callable) -> ClaimResult:
    opened: list = []  # every dataset this claim reads, to refuse numbers from a failed solver run

    def recording_open(path, _open=open_dataset):
        ds = _open(path)
        opened.append((path, ds))
        return ds

    m = MEASURE[claim.kind](claim, reading, recording_open)
    failures = solver_failures(opened)
    adequate = not claim.not_adequate  # set by stickslip.claims.models.annotate
    answer = model_answer(opened)
    status, detail = status_of(m, claim.comparable is not False and adequate, failures, answer)
    if status == "not-comparable":
        cause = not_comparable_cause(claim, m, failures)
    else:
        cause = ANSWER_CAUSES[answer.outcome] if answer is not None and m.holds is None else ""
    if not adequate and not failures:
        detail = f"{claim.not_adequate} | {detail}"
    members = member_failures(opened)
    caveats = [f"{len(members)} sweep runs diverged or failed: " + "; ".join(members)] if members else []
    caveats += [claim.model_values] if claim.model_values else []
    expected = _per_reading(claim.expected, reading, default="(not pinned)")
    return ClaimResult(
        claim=claim.id,
        reading=reading,
        section=claim.section,
        figure=claim.figure,
        kind=claim.kind,
        quantity=m.quantity,
        reported=m.reported,
        unit="" if claim.unit is None else claim.unit,
        measured=m.measured,
        reference=m.reference,
        deviation=m.deviation,
        margin=m.margin,
        spread=answer.spread if cause in ANSWER_CAUSES.values() else m.spread,
        status=status,
        expected=expected,
        matches_expected=(status == expected),
        evidence=claim.evidence,
        reason=reason_text(claim, reading, m, status, detail, failures, caveats, answer),
        quote=" ".join(claim.quote.split()),
        cause=cause,
        model=claim.model or "",
    )


def evaluate_all(claims: list[Claim], readings: list[str], open_dataset: Callable) -> list[ClaimResult]:
    return [evaluate(c, r, open_dataset) for c in claims for r in readings_of(c, readings)]
