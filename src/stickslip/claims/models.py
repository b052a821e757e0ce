"""Which model may decide a beam-on-disc claim: the beam only where the model comparison agrees.

Every beam-on-disc row names its deciding model (``model``, stickslip.claims.rows.MODELS). The model
comparison (results/fe/model_comparison.csv, stickslip.studies.fe_comparison) runs the continuum strip, the
paper's own kind of model, beside the beam on every scene; a row per (scene, quantity) says whether the two
agree under its stated rule. A dataset operand of a claim read from the beam (any dataset under
``results/fe/`` that is not the continuum's) whose scene and quantity have a comparison row that does not
agree cannot decide the claim: the beam is not the paper's model there. The claims table then calls the
claim not comparable with that reason (``Claim.not_adequate``), so its pinned status must say so too, or the
row be pointed at the continuum.

A row the beam decides needs more: a comparison row over the claim's own window (the continuum run over the
same 1 s, every scalar both models hold, at dt and dt/2) that agrees, for every beam operand; without one
the beam's value is no evidence either (``inadequacy``). The claim's reason cites both models' values at dt
and dt/2 from those rows (``Claim.model_values``).
"""

from __future__ import annotations

import csv
from collections.abc import Iterable, Mapping
from pathlib import Path

from ..catalogue import fe_model_of, last_name
from ..io.benchmarks import as_number as _num
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


def _window_row(comparison: Mapping[tuple[str, str], Mapping], scene: str, variable: str) -> Mapping | None:
    row = comparison.get((scene, variable))
    return row if row is not None and row.get("window") == "claim" else None


def _window_text(scene: str, variable: str, row: Mapping) -> str:
    return (
        f"{scene} {variable} over {_num(row['t_end']):g} s: beam {_num(row['beam']):.3g}/"
        f"{_num(row['beam_half_step']):.3g} vs continuum {_num(row['continuum']):.3g}/"
        f"{_num(row['continuum_half_step']):.3g} at dt/dt/2 ({row['note']})"
    )


def inadequacy(
    claim: ClaimRow,
    comparison: Mapping[tuple[str, str], Mapping],
    constituents: Mapping[str, list[tuple[str, str]]] | None = None,
) -> str:
    """Why the beam may not decide ``claim`` ("" when it may).

    A row the beam decides (``model: beam``) needs, for every beam operand, a comparison row over the
    claim's window (``window == "claim"``) for that scene and variable that agrees: one that disagrees, or
    none, and the beam's value is no evidence. A cross-scene ratio is checked through its two scenes'
    quantity (``constituents``: variable -> [(scene, variable), ...]). A beam operand of another row (the
    other side of a continuum row) is held to the comparison rows there are (its window's, else the short
    window's quantity)."""
    disagree, missing = [], []
    for path, variable in beam_operands(claim):
        scene = last_name(path)
        for sc, var in (constituents or {}).get(variable) or [(scene, variable)]:
            row = _window_row(comparison, sc, var)
            if row is not None:
                if not _agrees(row):
                    disagree.append(_window_text(sc, var, row))
                continue
            if claim.model == "beam":
                missing.append(f"{sc} {var}")
                continue
            quantity = COMPARED_AS.get(var)
            short = comparison.get((sc, quantity)) if quantity else None
            if short is not None and not _agrees(short):
                disagree.append(
                    f"{sc} {quantity}: beam {_num(short['beam']):.3g} vs continuum "
                    f"{_num(short['continuum']):.3g} ({short.get('window', 'short')} window; {short['note']})"
                )
    parts = []
    if disagree:
        parts.append("the model comparison disagrees on " + "; ".join(dict.fromkeys(disagree)))
    if missing:
        parts.append("no comparison over the claim's window checks " + ", ".join(dict.fromkeys(missing)))
    return ("the beam is not adequate here: " + "; ".join(parts)) if parts else ""


def model_values(claim: ClaimRow, comparison: Mapping[tuple[str, str], Mapping]) -> str:
    """Both models' values at dt and dt/2 from every comparison row over a claim's window that the claim's
    operands (beam or continuum) read; "" when there is none."""
    out = []
    for _, ref in claim.dataset_refs():
        scene, variable = last_name(ref.dataset), ref.variable or ""
        row = _window_row(comparison, scene, variable) or _window_row(
            comparison, scene, COMPARED_AS.get(variable, "")
        )
        if row is None:
            continue
        out.append(
            f"model comparison over {_num(row['t_end']):g} s, {scene} {row['quantity']} at dt/dt/2: beam "
            f"{_num(row['beam']):.3g}/{_num(row['beam_half_step']):.3g}, continuum "
            f"{_num(row['continuum']):.3g}/{_num(row['continuum_half_step']):.3g} "
            f"({'agree' if _agrees(row) else 'disagree'})"
        )
    return "; ".join(dict.fromkeys(out))


def annotate(
    claims: Iterable[Claim],
    comparison: Mapping[tuple[str, str], Mapping],
    cross_scene: Mapping[str, list] | None = None,
) -> list[Claim]:
    """Copies of the claims with ``not_adequate`` (why the comparison does not license a beam row) and
    ``model_values`` (the window comparison's values) set; both "" where they do not apply."""
    constituents = {name: [(a, var), (b, var)] for name, (a, b, var) in (cross_scene or {}).items()}
    out = []
    for c in claims:
        notes = {
            "not_adequate": inadequacy(c, comparison, constituents),
            "model_values": model_values(c, comparison),
        }
        out.append(c.model_copy(update=notes))
    return out
