"""Which model may decide a beam-on-disc claim: the beam only where the model comparison agrees.

Every beam-on-disc row names its deciding model (``model``, stickslip.claims.rows.MODELS). The model
comparison (results/fe/model_comparison.csv, stickslip.studies.fe_comparison) runs the continuum strip, the
paper's own kind of model, beside the beam on every scene; a row per (scene, quantity) says whether the two
agree under its stated rule. A dataset operand of a claim read from the beam (any dataset under
``results/fe/`` that is not the continuum's) whose scene and quantity have a comparison row that does not
agree cannot decide the claim: the beam is not the paper's model there. The claims table then calls the
claim not comparable with that reason (``Claim.not_adequate``), so its pinned status must say so too, or the
row be pointed at the continuum.

Where a comparison row over a claim's window exists (first-mode growth, the separation burst), the claim's
reason also cites both models' values at dt and dt/2 (``Claim.model_values``); where none does, the reason
says so (``unchecked``): the beam then decides unchecked over that window.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Iterable, Mapping
from pathlib import Path

from ..catalogue import fe_model_of, last_name
from .rows import Claim, ClaimRow

#: claim variables that measure one of the comparison's quantities (the same motion of node 1, read
#: another way): a disagreement in the quantity is one in the variable. A variable not listed has no
#: comparison row, and nothing here forbids the beam to decide it.
COMPARED_AS = {
    "horizontal_amplitude": "horizontal_amplitude",
    "max_horizontal_displacement": "horizontal_amplitude",
    "max_abs_horizontal_displacement": "horizontal_amplitude",
    "horizontal_displacement_envelope": "horizontal_amplitude",
    "mean_horizontal_displacement": "mean_horizontal_displacement",
    "abs_mean_horizontal_displacement": "mean_horizontal_displacement",
    "dominant_frequency": "dominant_frequency",
    "horizontal_nearest_mode_ratio": "dominant_frequency",
    "stick_fraction": "stick_fraction",
    "separation_fraction": "separation_fraction",
    "first_mode_growth_rate": "first_mode_growth_rate",
    "separation_burst_time": "separation_burst_time",
}


def read_comparison(path) -> dict[tuple[str, str], dict]:
    """(scene, quantity) -> the comparison row (values as written: strings)."""
    with Path(path).open(newline="") as fh:
        return {(r["scene"], r["quantity"]): r for r in csv.DictReader(fh)}


def beam_operands(claim: ClaimRow) -> list[tuple[str, str]]:
    """(dataset, variable) of every operand the claim reads from the beam model."""
    refs = [ref for _, ref in claim.dataset_refs()]
    return [(ref.dataset, ref.variable or "") for ref in refs if fe_model_of(ref.dataset) == "beam"]


def _agrees(row: Mapping) -> bool:
    return str(row["agreement"]).strip().lower() in ("true", "1")


def _num(text) -> float:
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def inadequacy(claim: ClaimRow, comparison: Mapping[tuple[str, str], Mapping]) -> str:
    """Why the beam may not decide ``claim`` ("" when it may): every beam operand whose (scene, quantity)
    comparison row disagrees, with the row's numbers and note (whatever model the row names: a continuum
    row may compare with a beam dataset)."""
    beam_refs = beam_operands(claim)  # a continuum row may still read the beam on its other side
    why = []
    for path, variable in beam_refs:
        scene, quantity = last_name(path), COMPARED_AS.get(variable)
        row = comparison.get((scene, quantity)) if quantity else None
        if row is None or _agrees(row):
            continue
        why.append(
            f"{scene} {quantity}: beam {_num(row['beam']):.3g} vs continuum {_num(row['continuum']):.3g} "
            f"({row.get('window', 'short')} window; {row['note']})"
        )
    return (
        ("the beam is not adequate here: the model comparison disagrees on " + "; ".join(why)) if why else ""
    )


def model_values(claim: ClaimRow, comparison: Mapping[tuple[str, str], Mapping]) -> str:
    """Both models' values at dt and dt/2 from every comparison row over a claim's window that the claim's
    operands (beam or continuum) read; "" when there is none."""
    out = []
    for _, ref in claim.dataset_refs():
        scene, quantity = last_name(ref.dataset), COMPARED_AS.get(ref.variable or "")
        row = comparison.get((scene, quantity)) if quantity else None
        if row is None or row.get("window") != "claim":
            continue
        out.append(
            f"model comparison over {_num(row['t_end']):g} s, {scene} {quantity} at dt/dt/2: beam "
            f"{_num(row['beam']):.3g}/{_num(row['beam_half_step']):.3g}, continuum "
            f"{_num(row['continuum']):.3g}/{_num(row['continuum_half_step']):.3g} "
            f"({'agree' if _agrees(row) else 'disagree'})"
        )
    return "; ".join(dict.fromkeys(out))


def unchecked(claim: ClaimRow, comparison: Mapping[tuple[str, str], Mapping]) -> str:
    """The beam operands no comparison row over the claim's window covers, in words ("" when none): the
    beam decides them unchecked against the continuum (the comparison covers 0.1 s, or nothing)."""
    short, none = [], []
    if claim.model != "beam":  # a closed form or the continuum decides it; a beam operand is then an input
        return ""
    for path, variable in beam_operands(claim):
        scene, quantity = last_name(path), COMPARED_AS.get(variable)
        row = comparison.get((scene, quantity)) if quantity else None
        if row is None:
            none.append(f"{scene} {variable}")
        elif row.get("window", "short") != "claim":
            short.append(f"{scene} {variable}")
    parts = []
    if none:
        parts.append("no model comparison covers " + ", ".join(dict.fromkeys(none)))
    if short:
        parts.append("the comparison covers only its short window for " + ", ".join(dict.fromkeys(short)))
    return ("beam value unchecked over the claim's window: " + "; ".join(parts)) if parts else ""


def annotate(claims: Iterable[Claim], comparison: Mapping[tuple[str, str], Mapping]) -> list[Claim]:
    """Copies of the claims with ``not_adequate`` (why the comparison does not license a beam row) and
    ``model_values`` (the window comparison's values) set; both "" where they do not apply."""
    out = []
    for c in claims:
        inadequate = inadequacy(c, comparison)  # not decided at all: no need to say what is unchecked
        values = [model_values(c, comparison)] + ([] if inadequate else [unchecked(c, comparison)])
        notes = {"not_adequate": inadequate, "model_values": "; ".join(filter(None, values))}
        out.append(c.model_copy(update=notes))
    return out
