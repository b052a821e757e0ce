"""A failed solver run is recorded in its dataset and reported as not-comparable, never as a result; a run
whose motion diverges, rests or never sticks is the model's answer, recorded with its mechanism, and decides
the claims it leaves unmeasured."""

import numpy as np
import pytest
from claim_rows import claim as claim_row

from stickslip.analysis.metrics import limit_cycle_metrics
from stickslip.claims.evaluate import evaluate
from stickslip.io import netcdf
from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.solvers import ExactSwitchSolver


@pytest.fixture(scope="module")
def good():
    return ExactSwitchSolver().solve(
        BeltModel.build(PAPER_BASELINE, "consistent"), 20.0, np.linspace(0, 20, 2001)
    )


def _failed_copy(traj, message):
    import dataclasses

    stats = dataclasses.replace(traj.stats, status="failed", message=message)
    return dataclasses.replace(traj, stats=stats)


def test_failed_status_recorded_in_dataset(good, tmp_path):
    bad = _failed_copy(good, "step size collapsed below 1e-12 s at t = 3.2 s")
    ds = netcdf.trajectory_dataset(bad, limit_cycle_metrics(bad, 5.0))
    assert int(ds.solver_status) == 1
    assert "step size collapsed" in ds.solver_status.attrs["message"]
    assert (
        np.isnan(float(ds.frequency_peaks)) and float(ds.solver_ok) == 0.0
    )  # every metric NaN: nothing measured


def test_nan_trajectory_is_a_failure_even_if_the_solver_says_ok(good):
    import dataclasses

    x = good.x.copy()
    x[100:] = np.nan
    ds = netcdf.trajectory_dataset(dataclasses.replace(good, x=x))
    assert int(ds.solver_status) == 1 and "non-finite" in ds.solver_status.attrs["message"]


def test_claim_on_failed_run_is_not_comparable(good):
    ok_ds = netcdf.trajectory_dataset(good, limit_cycle_metrics(good, 5.0))
    bad = _failed_copy(good, "blow-up: |x| > 1e6")
    bad_ds = netcdf.trajectory_dataset(bad, limit_cycle_metrics(bad, 5.0))
    bad_ds["frequency_peaks"] = ((), 0.25, {"units": "Hz"})  # even a plausible stray number is not compared
    claim = claim_row(variable="frequency_peaks", dataset="{reading}.nc", value=0.25, unit="Hz")
    result = evaluate(claim, "bad", lambda p: {"bad.nc": bad_ds, "ok.nc": ok_ds}[p])
    assert result.status == "not-comparable"
    assert result.reason.startswith("Not comparable: the solver run failed.")  # the conclusion first
    assert "solver failed" in result.reason and "blow-up" in result.reason  # then the failure message
    assert "solver failed" not in evaluate(claim, "ok", lambda p: {"ok.nc": ok_ds}[p]).reason


def test_written_dataset_keeps_its_own_attributes(good, tmp_path):
    ds = netcdf.trajectory_dataset(good)
    ds.attrs.update(title="my title", Conventions="CF-1.10", history="made by hand")
    path = netcdf.write_dataset(ds, tmp_path / "a.nc", scene={}, interpretation="x", method={}, title="other")
    out = netcdf.read_dataset(path)
    assert out.attrs["title"] == "my title"
    assert (
        out.attrs["history"].startswith("made by hand\n") and "written by stickslip" in out.attrs["history"]
    )
    import netCDF4

    with netCDF4.Dataset(path) as nc:
        assert "_FillValue" not in nc["time"].ncattrs()  # CF 2.5.1: coordinates have no fill value
        assert nc["time"].standard_name == "time"


@pytest.fixture(scope="module")
def scene_run(repo_root):
    """The build's own code path: one scene x reading of the repository's config, solved and measured."""
    from stickslip.pipeline.config import load_config
    from stickslip.schema import Onedof
    from stickslip.studies.onedof import scene_run_dataset
    from stickslip.studies.specs import run_spec

    onedof = Onedof.model_validate(load_config([repo_root / "config" / "config.yaml"])["onedof"])
    return lambda scene, reading: scene_run_dataset(run_spec(onedof, scene, reading, "exact"))


def test_a_diverging_scene_is_the_models_answer_with_its_mechanism_from_closed_form(scene_run):
    """Fig. 6 under the consistent caption reading: slip damping C - mu_s N sigma = 1.5 - 0.8*10*0.5 = -2.5
    and friction reversing beyond 1/sigma = 2 mm/s: the motion grows. Its first stick (x from 0 to the
    release point (mu_s N - C V_b)/K = 1.45 mm at V_b = 0.5 mm/s: 2.9 s) is computed before it diverges."""
    ds = scene_run("fig06", "consistent_caption")
    assert int(ds.solver_status) == 2 and ds.solver_status.attrs["flag_meanings"] == "ok failed diverged"
    assert ds.outcome.attrs["flag_meanings"].split()[int(ds.outcome)] == "diverged"
    why = ds.outcome.attrs["mechanism"]
    assert "C - mu_s N sigma = 1.5 - 4 = -2.5" in why and "1/sigma = 2 mm/s" in why
    assert float(ds.first_stick_time) == pytest.approx((0.8 * 10 - 1.5 * 0.5) / 5 / 0.5, rel=1e-9)
    assert np.isnan(float(ds.stick_time)) and np.isnan(float(ds.frequency_peaks))  # no cycle: NaN, but there
    claim = claim_row(variable="stick_time", dataset="{reading}.nc", value=4.6, unit="s")
    result = evaluate(claim, "fig06", lambda p: ds)
    assert result.status == "deviates" and result.cause == "model diverges"
    assert result.reason.startswith("Deviates, the model's answer: slip damping C - mu_s N sigma")


def test_printed_reading_rests_at_the_closed_form_sliding_equilibrium(scene_run):
    """As printed (Eq. 3), friction +mu_s N (sgn(v_r) - sigma v_r) pushes away from the belt speed, the slip
    damping C + mu_s N sigma = 4 > 0: the mass settles at K x = -mu_s N + mu_s N sigma V_b, x = -0.75 mm."""
    ds = scene_run("fig02", "eq3_caption")
    assert int(ds.solver_status) == 0
    assert ds.outcome.attrs["flag_meanings"].split()[int(ds.outcome)] == "rest"
    assert "x = -0.75 mm is stable" in ds.outcome.attrs["mechanism"]
    assert float(ds.max_displacement) == pytest.approx(-0.75, abs=1e-6)


def test_a_numerical_failure_is_not_an_answer_even_beside_one(good):
    """A sweep with one numerical failure among runs at rest decides nothing: the failed run might have held
    a cycle."""
    import xarray as xr

    ds = xr.Dataset(
        {
            "stick_time": ("mu_s", [np.nan, np.nan]),
            "outcome": ("mu_s", [2.0, 4.0]),  # rest, failed
            "outcome_mechanism": ("mu_s", np.array(["at rest", "numerical failure"], dtype=object)),
        },
        coords={"mu_s": [0.2, 0.5]},
    )
    rising = claim_row(kind="trend", coord="mu_s", sign=1, value=None, tolerance=None, unit=None,
                       dataset="s.nc", variable="stick_time")  # fmt: skip
    result = evaluate(rising, "", lambda p: ds)
    assert result.status == "not-comparable" and result.cause == "nothing"
    ds["outcome"] = ("mu_s", [2.0, 1.0])  # rest, no stick: both answers
    assert evaluate(rising, "", lambda p: ds).status == "deviates"
