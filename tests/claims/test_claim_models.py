"""The model that decides a beam-on-disc claim: named on every row, and the beam never deciding where the
model comparison finds it disagreeing with the continuum (the paper's kind of model)."""

import csv

import pytest
import xarray as xr
from pydantic import ValidationError

from stickslip.claims.evaluate import evaluate
from stickslip.claims.load import load_claims
from stickslip.claims.models import annotate, inadequacy, read_comparison
from stickslip.claims.rows import Claim, ClaimRow

BEAM = "results/fe/lower_face_drop/s10.nc"
CONT = "results/fe/continuum_window/s10.nc"
ROW = {
    "id": "c",
    "section": "10",
    "figure": "Fig. 27",
    "figures": [27],
    "quote": "q",
    "kind": "value",
    "dataset": BEAM,
    "variable": "max_horizontal_displacement",
    "value": 1e-4,
    "unit": "mm",
    "tolerance": {"rel": 0.25, "reason": "test"},
    "expected": "deviates",
    "evidence": "evidence",
    "model": "beam",
}


def _comparison(tmp_path, rows):
    path = tmp_path / "model_comparison.csv"
    keys = ["scene", "quantity", "continuum", "beam", "agreement", "note", "window", "t_end"]
    keys += ["beam_half_step", "continuum_half_step"]
    with path.open("w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in keys})
    return read_comparison(path)


def test_a_beam_on_disc_row_names_a_model_that_matches_its_dataset():
    ClaimRow.model_validate(ROW)
    with pytest.raises(ValidationError, match="names its model"):
        ClaimRow.model_validate({k: v for k, v in ROW.items() if k != "model"})
    with pytest.raises(ValidationError, match="subject dataset"):
        ClaimRow.model_validate({**ROW, "model": "continuum"})
    with pytest.raises(ValidationError, match="subject dataset"):
        ClaimRow.model_validate({**ROW, "dataset": CONT})
    with pytest.raises(ValidationError, match="only a beam-on-disc row"):
        ClaimRow.model_validate({**ROW, "dataset": "results/onedof/x.nc"})


def test_every_claim_is_shown_only_on_cards_of_its_own_half_of_the_paper():
    """A card lists the claims of its figures: a beam-on-disc claim on a 1-DOF figure's card (or the
    reverse) would put the other half's dataset there."""
    from glob import glob

    from stickslip.presentation.page import paper_spec

    half = {e["number"]: e["half"] for e in paper_spec()["figures"]}
    wrong = []
    for c in load_claims(sorted(glob("config/claims/*.yaml"))):
        paths = c.dataset_paths()
        if paths:
            mine = "fe" if all(p.startswith("results/fe/") for p in paths) else "onedof"
            wrong += [(c.id, n) for n in c.figures if half.get(n, mine) != mine]
    assert wrong == []


def test_every_beam_on_disc_row_of_the_project_names_its_model():
    rows = load_claims(["config/claims/sections_09_12.yaml"])
    fe = [c for c in rows if any(p.startswith("results/fe/") for p in c.dataset_paths())]
    assert fe and all(c.model in ("beam", "continuum", "reduced", "closed_form", "peer") for c in fe)
    # Section 10 is decided by the model of its literal setup (upper face held): the continuum
    assert all(c.model == "continuum" for c in rows if c.section == "10")


def test_a_beam_row_whose_comparison_disagrees_is_not_decided(tmp_path):
    ds = xr.Dataset({"max_horizontal_displacement": 3e-4})
    # over the claim's window, for the variable the row reads, at dt and dt/2
    disagree = {"scene": "s10", "quantity": "max_horizontal_displacement"}
    disagree |= {"continuum": "1e-8", "beam": "3e-4", "agreement": "False", "note": "not the same model"}
    disagree |= {"window": "claim", "t_end": "1.0"}
    disagree |= {"continuum_half_step": "1e-8", "beam_half_step": "3e-4"}
    (row,) = annotate([Claim.model_validate(ROW)], _comparison(tmp_path, [disagree]))
    assert row.not_adequate.startswith("the beam is not adequate here")
    assert "(disagree)" in row.model_values
    result = evaluate(row, "", lambda path: ds)
    assert result.status == "not-comparable"
    assert "the beam is not adequate here" in result.reason and "not the same model" in result.reason
    # the same row where the models agree is decided as before
    agree = {**disagree, "agreement": "True", "note": ""}
    (row,) = annotate([Claim.model_validate(ROW)], _comparison(tmp_path, [agree]))
    assert row.not_adequate == ""
    assert evaluate(row, "", lambda path: ds).status == "deviates"
    # the continuum's own row is never held back by the beam's disagreement
    continuum = Claim.model_validate({**ROW, "dataset": CONT, "model": "continuum"})
    (row,) = annotate([continuum], _comparison(tmp_path, [disagree]))
    assert evaluate(row, "", lambda path: ds).status == "deviates"


def test_a_beam_operand_on_the_other_side_of_a_continuum_row_is_checked_too(tmp_path):
    row = {k: v for k, v in ROW.items() if k not in ("dataset", "variable", "value", "unit", "tolerance")}
    row |= {"kind": "compare", "relation": ">", "model": "continuum"}
    row |= {"lhs": {"dataset": CONT, "variable": "max_horizontal_displacement"}}
    row |= {"rhs": {"dataset": BEAM, "variable": "max_horizontal_displacement"}}
    disagree = {"scene": "s10", "quantity": "horizontal_amplitude", "continuum": "1", "beam": "2"}
    disagree |= {"agreement": "False", "note": "n", "window": "short"}
    (annotated,) = annotate([Claim.model_validate(row)], _comparison(tmp_path, [disagree]))
    assert evaluate(annotated, "", lambda path: xr.Dataset({"max_horizontal_displacement": 1.0})).status == (
        "not-comparable"
    )


def test_a_growth_verdict_cites_both_models_at_both_steps(tmp_path):
    window = {"scene": "s10", "quantity": "first_mode_growth_rate", "continuum": "0.523", "beam": "0.565"}
    window |= {"agreement": "True", "note": "", "window": "claim", "t_end": "1.0"}
    window |= {"beam_half_step": "0.536", "continuum_half_step": "0.570"}
    row = {**ROW, "kind": "compare", "relation": ">", "rhs": {"value": 0.0}}
    row = {k: v for k, v in row.items() if k not in ("dataset", "variable", "value", "unit", "tolerance")}
    row["lhs"] = {"dataset": BEAM, "variable": "first_mode_growth_rate"}
    (annotated,) = annotate([Claim.model_validate(row)], _comparison(tmp_path, [window]))
    result = evaluate(annotated, "", lambda path: xr.Dataset({"first_mode_growth_rate": 0.565}))
    assert result.status == "reproduced"
    assert "beam 0.565/0.536, continuum 0.523/0.57 (agree)" in result.reason


def _window(agree="True", beam=("1.0", "1.0"), cont=("1.0", "1.0")):
    return {"window": "claim", "agreement": agree, "t_end": "1.0", "beam": beam[0], "beam_half_step": beam[1],
            "continuum": cont[0], "continuum_half_step": cont[1], "note": "n"}  # fmt: skip


def test_a_beam_decided_row_counts_only_where_a_comparison_over_its_window_agrees():
    row = ClaimRow.model_validate({**ROW, "dataset": BEAM, "model": "beam"})
    assert inadequacy(row, {("s10", "max_horizontal_displacement"): _window()}) == ""
    missing = inadequacy(row, {("s10", "horizontal_amplitude"): {"window": "short", "agreement": "True"}})
    assert missing == (
        "the beam is not adequate here: no comparison over the claim's window checks s10 "
        "max_horizontal_displacement"
    )
    disagree = inadequacy(row, {("s10", "max_horizontal_displacement"): _window("False", cont=("3", "2"))})
    assert disagree.startswith("the beam is not adequate here: the model comparison disagrees on s10 ")
    assert "beam 1/1 vs continuum 3/2 at dt/dt/2" in disagree
    # a ratio of two beam scenes is checked through both scenes' quantity
    ratio = ClaimRow.model_validate({**ROW, "dataset": "results/fe/lower_face_drop/cross_scene.nc",
                                     "variable": "r", "model": "beam"})  # fmt: skip
    both = {("a", "v"): _window(), ("b", "v"): _window()}
    assert inadequacy(ratio, both, {"r": [("a", "v"), ("b", "v")]}) == ""
    assert "checks b v" in inadequacy(ratio, {("a", "v"): _window()}, {"r": [("a", "v"), ("b", "v")]})
