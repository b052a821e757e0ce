"""Metrics on synthetic signals with known answers."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from stickslip.analysis.metrics import (
    count_peaks,
    frequency_from_peaks,
    frequency_from_spectrum,
    limit_cycle_metrics,
    phase_runs,
    segment_runs,
)
from stickslip.solvers.base import SolverStats, Trajectory


@settings(max_examples=25, deadline=None)
@given(f=st.floats(0.1, 2.0), phase=st.floats(0, 2 * np.pi), offset=st.floats(-3, 3))
def test_peak_and_spectrum_frequencies_agree_on_a_clean_sine(f, phase, offset):
    t = np.arange(0, 60, 0.005)
    x = offset + np.sin(2 * np.pi * f * t + phase)
    assert frequency_from_peaks(t, x) == pytest.approx(f, rel=2e-3)
    assert frequency_from_spectrum(t, x) == pytest.approx(f, rel=2e-3)


def test_peak_count_in_a_window():
    t = np.arange(0, 18, 0.01)
    x = np.sin(2 * np.pi * 0.25 * t)  # maxima at 1, 5, 9, 13, 17 s
    assert count_peaks(t, x, 0, 18) == 5
    assert count_peaks(t, x, 0, 16) == 4


def test_phase_runs_from_samples():
    t = np.arange(10.0)
    phase = np.array([0, 0, 0, -1, -1, 1, 0, 0, -1, -1])
    stick, slip = phase_runs(t, phase)
    np.testing.assert_allclose(stick, [[0, 2.5], [5.5, 7.5]])
    np.testing.assert_allclose(slip, [[2.5, 5.5], [7.5, 9]])


def test_segment_runs_merge_slips_and_keep_grazing_touches():
    seg = np.array([[0, 1, 0], [1, 2, -1], [2, 2.5, 1], [2.5, 2.5, 0], [2.5, 4, -1], [4, 5, 0]])
    stick, slip = segment_runs(seg)
    np.testing.assert_allclose(stick, [[0, 1], [2.5, 2.5], [4, 5]])
    np.testing.assert_allclose(slip, [[1, 2.5], [2.5, 4]])


def _trajectory(t, x, v, phase, segments=None):
    return Trajectory(
        t=t,
        x=x,
        v=v,
        phase=phase,
        belt_velocity=np.full_like(t, 0.5),
        stats=SolverStats(),
        method="synthetic",
        segments=segments,
    )


def test_limit_cycle_metrics_of_a_sawtooth_with_known_intervals():
    # stick 2 s moving with the belt from 0 to 1 mm, slip 1 s back along a half cosine: period 3 s
    dt = 0.001
    t = np.arange(0, 30 + dt / 2, dt)
    tau = np.mod(t, 3.0)
    stick = tau < 2.0
    x = np.where(stick, 0.5 * tau, 0.5 + 0.5 * np.cos(np.pi * (tau - 2.0)))
    v = np.where(stick, 0.5, -0.5 * np.pi * np.sin(np.pi * (tau - 2.0)))
    phase = np.where(stick, 0, -1).astype(np.int8)
    m = limit_cycle_metrics(_trajectory(t, x, v, phase), transient=3.0)
    assert m["stick_time"].value == pytest.approx(2.0, abs=2 * dt)
    assert m["slip_time"].value == pytest.approx(1.0, abs=2 * dt)
    assert m["frequency_peaks"].value == pytest.approx(1 / 3, rel=1e-3)
    assert m["amplitude_peak_to_peak"].value == pytest.approx(1.0, abs=1e-6)
    assert m["max_speed"].value == pytest.approx(0.5 * np.pi, rel=1e-5)
    assert m["max_speed_position"].value == pytest.approx(0.5, abs=1e-3)
    assert m["stick_end_position"].value == pytest.approx(1.0, abs=1e-3)
    assert m["stick_velocity"].value == pytest.approx(0.5)
    assert m["periodic"].value == 1.0


def test_failed_run_has_every_metric_nan_but_the_failure_flag_and_outcome():
    from stickslip.analysis.metrics import CYCLE_METRICS
    from stickslip.analysis.outcome import outcome_code

    t = np.linspace(0, 1, 11)
    traj = _trajectory(t, np.full_like(t, np.nan), np.full_like(t, np.nan), np.zeros(11, np.int8))
    traj.stats.status = "failed"
    m = limit_cycle_metrics(traj, 0.0)
    assert list(m) == list(CYCLE_METRICS) and m["solver_ok"].value == 0.0
    assert m["outcome"].value == outcome_code("failed")
    assert all(np.isnan(v.value) for k, v in m.items() if k not in ("solver_ok", "outcome"))


def test_a_run_that_comes_to_rest_has_no_frequency():
    t = np.arange(0, 40, 0.01)
    x = -0.85 * (1 - np.exp(-t)) + 1e-9 * np.sin(2 * np.pi * 0.6 * t)  # settles, then round-off wiggles
    traj = _trajectory(t, x, np.gradient(x, t), np.full(t.shape, -1, np.int8))
    m = limit_cycle_metrics(traj, transient=10.0)
    assert np.isnan(m["frequency_peaks"].value) and np.isnan(m["frequency_spectrum"].value)


def test_friction_along_a_solution_ignores_switching_samples():
    from stickslip.analysis.friction_curve import friction_along_solution
    from stickslip.analysis.metrics import extra_metrics
    from stickslip.model import PAPER_BASELINE, friction_law

    law = friction_law(PAPER_BASELINE.with_(sigma=0.5), "consistent")
    v = np.array([0.5, 0.5, 0.2, -0.3, 0.5])  # the second sample is slip-labelled but at v_r = 0
    vb = np.full_like(v, 0.5)
    phase = np.array([0, -1, -1, -1, 0], dtype=np.int8)
    speed, mu = friction_along_solution(v, vb, phase, law, PAPER_BASELINE.normal_force)
    np.testing.assert_allclose(speed, [0.3, 0.8])
    np.testing.assert_allclose(mu, [0.5 * (1 - 0.5 * 0.3), 0.5 * (1 - 0.5 * 0.8)])
    t = np.arange(5.0)
    m = extra_metrics(t, np.zeros(5), v, vb, phase, law, PAPER_BASELINE.normal_force)
    assert m["friction_min_slip"] == pytest.approx(0.5 * (1 - 0.5 * 0.8))


def test_every_measured_metric_is_registered_with_its_units():
    """The registry is the one place a metric's units and long name are written: a baseline run's limit-cycle
    table and extra metrics carry exactly the registry's attributes."""
    from stickslip.analysis.metrics import METRICS, extra_metrics, limit_cycle_metrics, metric_attrs
    from stickslip.model import PAPER_BASELINE, BeltModel
    from stickslip.solvers import make_solver

    model = BeltModel.build(PAPER_BASELINE, "consistent")
    traj = make_solver("exact").solve(model, 40.0, np.linspace(0, 40, 4001))
    table = limit_cycle_metrics(traj, 10.0, count_window=18.0)
    extra = extra_metrics(traj.t, traj.x, traj.v, traj.belt_velocity, traj.phase, model.friction, 10.0)
    assert set(table) | set(extra) | {"slip_fraction"} == set(METRICS)
    for name, m in table.items():
        assert (m.units, m.long_name) == tuple(metric_attrs(name, count_window=18.0).values()), name
    assert table["peaks_in_count_window"].long_name == "displacement maxima in the first 18 s"
