"""The 1-DOF study datasets against what their physics fixes: one invariant per dataset builder.

Each builder runs on the repository config's own run specs (short windows where a study allows it)."""

import numpy as np
import pytest

from stickslip.pipeline.config import load_config
from stickslip.schema import Onedof
from stickslip.studies.onedof import critical_speed_dataset, eq6_dataset, friction_table_dataset
from stickslip.studies.specs import baseline_spec, run_spec

from project_run import ROOT


@pytest.fixture(scope="module")
def config():
    return Onedof.model_validate(load_config(sorted((ROOT / "config").glob("*.yaml")))["onedof"])


@pytest.mark.parametrize("reading", ["consistent_caption", "plateau_text"])
def test_the_friction_table_is_the_readings_law_along_the_solution(config, reading):
    spec = run_spec(config, "fig02", reading, "exact")
    ds = friction_table_dataset(spec, bins=24)
    p = spec.params
    v = ds.sample_relative_speed.values
    assert v.size > 100 and np.all(v >= 0)
    clipped = np.minimum(v, p.plateau_speed) if np.isfinite(p.plateau_speed or np.inf) else v
    # every slip sample obeys |F|/N = mu_s (1 - sigma |v_r|), capped at the plateau: the reading's own law
    np.testing.assert_allclose(ds.sample_mu.values, p.mu_s * (1 - p.sigma * clipped), rtol=0, atol=1e-12)
    table = ds.mu.values
    assert table[0] == pytest.approx(p.mu_s) and ds.relative_speed.values[0] == 0.0
    assert np.all(np.diff(ds.relative_speed.values) > 0) and np.all(np.diff(table) <= 1e-12)
    assert float(ds.mu_static) == p.mu_s


def test_eq6_peaks_are_the_maxima_of_the_tabulated_curves(config):
    ds = eq6_dataset(baseline_spec(config), f_max=1.0, points=4001)
    f = ds.frequency.values
    df = f[1] - f[0]
    for curve, peak_f, peak_a in (
        ("amplitude_printed", "peak_frequency_printed", "peak_amplitude_printed"),
        ("amplitude_correct", "peak_frequency_correct", "peak_amplitude_correct"),
    ):
        y = ds[curve].values
        assert abs(f[np.argmax(y)] - float(ds[peak_f])) <= df
        assert float(ds[peak_a]) >= y.max() - 1e-12 and float(ds[peak_a]) == pytest.approx(y.max(), rel=1e-5)
    # at zero frequency both curves are the static deflection F / K
    static = float(ds.force) / baseline_spec(config).params.stiffness
    assert ds.amplitude_printed.values[0] == pytest.approx(static)
    assert ds.amplitude_correct.values[0] == pytest.approx(static)


def test_the_critical_speed_separates_sticking_runs_from_sliding_ones(config):
    spec = baseline_spec(config, "plateau_caption")
    speeds = np.array([0.1, 0.3, 0.5, 0.7, 1.0, 1.5])
    ds = critical_speed_dataset(spec, speeds, t_end=40.0, transient=20.0)
    vc = float(ds.critical_belt_speed)
    sticks = ds.stick_fraction.values > 0
    assert np.all(ds.solver_ok.values == 1)
    assert 0 < vc < np.inf and float(ds.has_critical_speed) == 1.0
    assert not np.any(sticks[speeds >= vc]) and sticks[speeds < vc][-1]
    # beyond the plateau speed (0.6 mm/s) friction no longer falls with speed: steady sliding is stable there,
    # and below it the falling branch's negative damping sigma mu_s N = 2.5 exceeds C = 1.5
    plateau = spec.params.plateau_speed
    assert float(ds.steady_sliding_stable_from) == speeds[speeds > plateau][0]
    assert np.all(ds.steady_sliding_stable.values[speeds < plateau] == 0)
