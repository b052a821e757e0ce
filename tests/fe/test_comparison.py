"""The beam (20 frame elements with rotary inertia, lower-face contact) against the continuum strip with the
paper's 100 x 1 mesh: same mapping, same window, node-1 metrics within 5 %; the agreement column never
calls a difference beyond 5 % agreement unless the measured noise floor covers both numbers."""

import pytest
import xarray as xr

from stickslip.fe.params import FrictionTable
from stickslip.studies.fe_comparison import (
    AGREEMENT_REL,
    QUANTITIES,
    agrees,
    comparison_rows,
    noise_floors,
    relative_difference,
)
from stickslip.studies.fe_config import halved_step
from stickslip.studies.fe_continuum import continuum_dataset
from stickslip.studies.fe_scene import run_scene

FIG17 = FrictionTable.paper_fig17()


@pytest.mark.parametrize(
    "disc,contact",
    [
        ({"speed_rev_per_min": 15.2}, {"method": "kinematic"}),
        ({"speed_rev_per_min": 15.2}, {"angle_deg": 30.0}),
    ],
)
def test_beam_matches_continuum_on_a_drop(disc, contact):
    mapping = {
        "beam": {"n_elements": 20},
        "disc": disc,
        "contact": contact,
        "solver": {
            "t_end": 0.02,
            "initial_state": "drop",
            "stiffness_damping": 5e-9,
            "output_dt": 5e-6,
        },
    }
    cont = continuum_dataset(mapping, FIG17, nx=100, ny=1, name="s")
    beam = run_scene(mapping, FIG17)[1]
    floors = {"s": noise_floors(beam, run_scene(halved_step(mapping), FIG17)[1])}
    rows = comparison_rows({"s": cont}, {"s": beam}, floors=floors)
    for r in rows:
        if r["quantity"] in ("horizontal_amplitude", "mean_horizontal_displacement", "dominant_frequency"):
            assert r["agreement"], r
        assert_agreement_is_honest(r)
    assert float(cont["horizontal_amplitude"]) > 1e-5  # a real ring, not round-off agreeing with round-off


def assert_agreement_is_honest(row):
    """False whenever |relative difference| > 5 %, unless both values lie inside the noise floor."""
    inside = max(abs(row["continuum"]), abs(row["beam"])) <= row["noise_floor"]
    if abs(row["relative_difference"]) > AGREEMENT_REL and not inside:
        assert row["agreement"] is False, row
    assert str(AGREEMENT_REL) in row["agreement_rule"] and "noise_floor" in row["agreement_rule"]


def test_relative_difference_and_noise_floor():
    assert relative_difference(2.0, 2.1) == pytest.approx(0.05)
    assert relative_difference(0.0, 0.0) == 0.0 and relative_difference(0.0, 1e-3) == float("inf")
    # fractions are compared relatively: no absolute floor of its own
    assert not agrees(0.0, 0.004) and not agrees(0.30, 0.36) and not agrees(0.998, 0.02)
    # inside a measured noise floor neither number is a result
    assert agrees(0.0, 0.004, noise_floor=0.01) and not agrees(0.0, 0.004, noise_floor=0.003)
    assert not agrees(0.05, 0.5, noise_floor=0.1)  # only one of the two inside the floor


def test_agreement_column_false_beyond_5_percent_outside_the_noise_floor():
    """Rows built from the differences the old table flagged (-98 %, -100 %, +946 %, a frequency of a
    signal thousands of times smaller): every one outside its floor is false."""
    cases = [(0.05, 0.001, 0.004), (0.12, 0.0, 0.01), (0.011, 0.115, 0.002), (366.0, 12900.0, 1.0)]
    cont, beam, floors = {}, {}, {}
    for i, (c, b, fl) in enumerate(cases):
        name = f"s{i}"
        cont[name] = xr.Dataset({q: ((), c) for q in QUANTITIES})
        beam[name] = {q: b for q in QUANTITIES}
        floors[name] = {q: fl for q in QUANTITIES}
    rows = comparison_rows(cont, beam, {"s0": "why"}, floors)
    assert len(rows) == len(cases) * len(QUANTITIES)
    for r in rows:
        assert_agreement_is_honest(r)
        assert r["agreement"] is False
    assert all(r["note"] == "why" for r in rows if r["scene"] == "s0")


def test_frequency_of_motions_of_different_size_does_not_agree():
    """Equal dominant frequencies of a 9e-6 mm and a 1.4e-9 mm motion are not one result."""
    cont = {"s": xr.Dataset({q: ((), 1.0) for q in QUANTITIES})}
    cont["s"]["horizontal_amplitude"] = ((), 1.4e-9)
    beam = {"s": {**{q: 1.0 for q in QUANTITIES}, "horizontal_amplitude": 9.2e-6}}
    rows = {r["quantity"]: r for r in comparison_rows(cont, beam)}
    assert rows["dominant_frequency"]["relative_difference"] == 0.0
    assert (
        rows["dominant_frequency"]["agreement"] is False
        and rows["horizontal_amplitude"]["agreement"] is False
    )
    assert rows["mean_horizontal_displacement"]["agreement"] is True
