"""A failed solver run is recorded in its dataset and reported as not-comparable, never as a result."""

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
    assert "frequency_peaks" not in ds and float(ds.solver_ok) == 0.0  # no metrics measured on a failed run


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
