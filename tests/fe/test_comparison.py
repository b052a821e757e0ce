"""The beam (20 frame elements with rotary inertia, lower-face contact) against the continuum strip with the
paper's 100 x 1 mesh: same mapping, same window, node-1 metrics within 5 %."""

import pytest

from stickslip.fe.params import FrictionTable
from stickslip.studies.fe_comparison import (
    agrees,
    beam_metrics,
    comparison_rows,
    continuum_dataset,
    relative_difference,
)

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
    beam = beam_metrics(mapping, FIG17)
    rows = comparison_rows({"s": cont}, {"s": beam})
    for r in rows:
        if r["quantity"] in ("horizontal_amplitude", "mean_horizontal_displacement", "dominant_frequency"):
            assert r["within_5_percent"], r
    assert float(cont["horizontal_amplitude"]) > 1e-5  # a real ring, not round-off agreeing with round-off


def test_relative_difference_and_fraction_floor():
    assert relative_difference(2.0, 2.1) == pytest.approx(0.05)
    assert relative_difference(0.0, 0.0) == 0.0 and relative_difference(0.0, 1e-3) == float("inf")
    assert agrees(0.0, 0.004, "separation_fraction") and not agrees(0.0, 0.004, "horizontal_amplitude")
    assert not agrees(0.30, 0.36, "stick_fraction")
