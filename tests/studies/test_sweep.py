"""Sweeps: chunks tile the grid, merge back to the unchunked result, linked parameters follow their axis."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from stickslip.analysis.sweep import (
    SweepAxis,
    chunk_count,
    chunk_dataset,
    chunk_points,
    grid_size,
    merge_chunks,
    run_points,
)
from stickslip.model import PAPER_BASELINE, ParameterError
from stickslip.solvers import ExactSwitchSolver

AXES = [
    SweepAxis("belt_velocity", (0.3, 0.5, 0.8), "mm s-1"),
    SweepAxis("mass", (1.0, 2.0), "kg", linked={"normal_force": 10.0}),
]


@settings(max_examples=30, deadline=None)
@given(chunk_size=st.integers(1, 8))
def test_chunks_tile_the_grid_exactly_once(chunk_size):
    points = [p for c in range(chunk_count(AXES, chunk_size)) for p in chunk_points(AXES, chunk_size, c)]
    assert len(points) == grid_size(AXES) == 6
    assert len({tuple(sorted(p.items())) for p in points}) == 6
    assert all(p["normal_force"] == 10.0 * p["mass"] for p in points)


def run(chunk_size):
    t = np.linspace(0, 20, 2001)
    solver = ExactSwitchSolver()
    base = PAPER_BASELINE.with_(sigma=0.5)
    parts = []
    for c in range(chunk_count(AXES, chunk_size)):
        res = run_points(base, "consistent", chunk_points(AXES, chunk_size, c), solver, 20.0, t, 8.0)
        parts.append(chunk_dataset(AXES, chunk_size, c, res))
    return merge_chunks(AXES, parts)


def test_merged_chunks_equal_the_unchunked_sweep():
    whole, chunked = run(6), run(4)
    assert whole.frequency_peaks.dims == ("belt_velocity", "mass")
    for name in whole.data_vars:
        np.testing.assert_array_equal(whole[name].values, chunked[name].values)
    # a point of the grid equals a single run with the same parameters
    single = run_points(
        PAPER_BASELINE.with_(sigma=0.5, belt_velocity=0.8, mass=2.0, normal_force=20.0),
        "consistent",
        [{}],
        ExactSwitchSolver(),
        20.0,
        np.linspace(0, 20, 2001),
        8.0,
    )
    for name in ("stick_time", "frequency_spectrum", "amplitude_peak_to_peak"):
        np.testing.assert_equal(float(whole[name].sel(belt_velocity=0.8, mass=2.0)), single[name][0])


def test_missing_chunk_is_an_error():
    parts = [
        chunk_dataset(
            AXES,
            4,
            0,
            run_points(
                PAPER_BASELINE,
                "consistent",
                chunk_points(AXES, 4, 0),
                ExactSwitchSolver(),
                5.0,
                np.linspace(0, 5, 51),
                1.0,
            ),
        )
    ]
    with pytest.raises(ValueError, match="cover 4 of 6"):
        merge_chunks(AXES, parts)


def test_bad_axes_and_chunks_name_the_problem():
    with pytest.raises(ParameterError, match="mass"):
        SweepAxis("mass", ())
    with pytest.raises(ParameterError, match="chunk"):
        chunk_points(AXES, 4, 5)


def _sweep_config(law=None, method="switch"):
    from glob import glob

    from stickslip.pipeline.config import load_config

    from project_run import ROOT

    config = load_config(sorted(glob(str(ROOT / "config" / "*.yaml"))) + [ROOT / "config/test/onedof.yaml"])
    config["onedof"]["methods"]["switch"] = {"solver": "switch"}
    sweep = {**config["onedof"]["sweeps"]["fig12"], "method": method, "law": law}
    config["onedof"]["sweeps"]["with_law"] = sweep
    return config


def test_a_sweep_with_the_readings_own_affine_law_matches_the_exact_sweep():
    """Issue 13 item 6: sweeps accept any friction law; given the reading's own affine law the switch-solver
    sweep reproduces the exact solver's (paper values and their time series)."""
    from stickslip.schema import Onedof
    from stickslip.studies.onedof import sweep_from_config

    config = Onedof.model_validate(_sweep_config({"kind": "affine", "mu_s": 0.5, "sigma": 0.5})["onedof"])
    exact = sweep_from_config(config, sweep="fig12", reading="consistent_caption", dense=False)
    switch = sweep_from_config(config, sweep="with_law", reading="consistent_caption", dense=False)
    assert "affine" in switch.attrs["friction_law"].lower()
    assert int(exact.solver_ok.sum()) == exact.solver_ok.size == int(switch.solver_ok.sum())
    for name in ("amplitude_peak_to_peak", "stick_fraction", "frequency_peaks"):
        np.testing.assert_allclose(switch[name].values, exact[name].values, rtol=1e-6, err_msg=name)
    np.testing.assert_allclose(switch.displacement.values, exact.displacement.values, atol=1e-7)


def test_a_sweep_law_needs_the_switch_method_and_valid_parameters():
    from stickslip.pipeline.config import ConfigError, validate_config

    table = ["results/onedof/friction_mu_vr.csv"]  # written by a rule: need not exist yet
    with pytest.raises(ConfigError, match="onedof.sweeps.with_law.method"):
        coulomb = {"kind": "coulomb", "mu_s": 0.5, "mu_k": 0.3}
        validate_config(_sweep_config(coulomb, "exact"), producible=table)
    with pytest.raises(ConfigError, match="onedof.sweeps.with_law.law.v_s"):
        validate_config(_sweep_config({"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.3}), producible=table)
