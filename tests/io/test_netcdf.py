"""Datasets carry units, long names and provenance, and are written atomically."""

import re

import numpy as np
import pytest
import xarray as xr

from stickslip.analysis.metrics import limit_cycle_metrics
from stickslip.io import netcdf
from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.solvers import ExactSwitchSolver


@pytest.fixture
def baseline_dataset():
    traj = ExactSwitchSolver().solve(
        BeltModel.build(PAPER_BASELINE, "consistent"), 20.0, np.linspace(0, 20, 2001)
    )
    return netcdf.trajectory_dataset(traj, limit_cycle_metrics(traj, 5.0))


def test_every_variable_has_units_and_long_name(baseline_dataset, tmp_path):
    path = netcdf.write_dataset(
        baseline_dataset,
        tmp_path / "a.nc",
        scene={"name": "x", "sigma": 0.3, "flag": True, "none": None, "list": [1, 2]},
        interpretation={"variant": "consistent"},
        method={"name": "exact"},
    )
    ds = netcdf.read_dataset(path)
    for name, var in ds.variables.items():
        assert "units" in var.attrs, name
        assert "long_name" in var.attrs, name
    for key in (
        "Conventions",
        "title",
        "source",
        "history",
        "references",
        "interpretation",
        "scene_sigma",
        "method_name",
    ):
        assert key in ds.attrs, key
    assert ds.attrs["scene_flag"] == 1 and ds.attrs["scene_list"] == "[1, 2]"
    assert ds.attrs["source"].startswith("stickslip ")


def test_interrupted_write_leaves_nothing(baseline_dataset, tmp_path, monkeypatch):
    def boom(self, *args, **kwargs):
        open(args[0], "w").write("partial")
        raise KeyboardInterrupt

    monkeypatch.setattr(xr.Dataset, "to_netcdf", boom)
    with pytest.raises(KeyboardInterrupt):
        netcdf.write_dataset(baseline_dataset, tmp_path / "b.nc", scene={}, interpretation="x", method={})
    assert list(tmp_path.iterdir()) == []


def test_missing_dataset_error_names_the_file(tmp_path):
    with pytest.raises(FileNotFoundError, match="nope.nc"):
        netcdf.read_dataset(tmp_path / "nope.nc")


def test_written_datasets_are_readable_like_any_new_file(baseline_dataset, tmp_path):
    import os

    path = netcdf.write_dataset(baseline_dataset, tmp_path / "p.nc", scene={}, interpretation="x", method={})
    mask = os.umask(0)
    os.umask(mask)
    assert (path.stat().st_mode & 0o777) == (0o666 & ~mask)


def test_text_results_get_the_same_mode_as_datasets(baseline_dataset, tmp_path):
    """Decks and tables (write_text_atomic, write_csv_atomic) are published like datasets: one mode for every
    result, not the owner-only mode of mkstemp."""
    import os

    from stickslip.io.text_files import write_csv_atomic, write_text_atomic

    data = netcdf.write_dataset(baseline_dataset, tmp_path / "d.nc", scene={}, interpretation="", method={})
    deck = write_text_atomic(tmp_path / "deck.inp", "*HEADING\n")
    table = write_csv_atomic(tmp_path / "t.csv", [{"a": 1}])
    modes = {p.name: p.stat().st_mode & 0o777 for p in (data, deck, table)}
    mask = os.umask(0)
    os.umask(mask)
    assert modes == dict.fromkeys(modes, 0o666 & ~mask)


def test_text_dimensions_are_written_as_index_plus_labels_and_read_back_labelled(tmp_path):
    """CF wants numeric dimension coordinates: a text dimension is written as an integer index with the
    labels in an auxiliary coordinate, and read_dataset gives the labelled dimension back."""
    import numpy as np
    import xarray as xr

    from stickslip.io.netcdf import read_dataset, write_dataset

    ds = xr.Dataset(
        {"value": (("scene", "quantity"), np.arange(6.0).reshape(2, 3), {"units": "1"})},
        coords={"scene": ["s1", "s2"], "quantity": ("quantity", ["a", "b", "c"], {"long_name": "quantity"})},
    )
    path = write_dataset(ds, tmp_path / "labelled.nc", scene={}, interpretation="test", method={})
    with xr.open_dataset(path) as raw:
        assert raw.scene.dtype.kind == "i" and list(raw.scene_label.values) == ["s1", "s2"]
        assert raw.quantity.attrs["units"] == "1" and raw.quantity_label.attrs["long_name"] == "quantity"
    back = read_dataset(path)
    assert list(back.scene.values) == ["s1", "s2"] and "scene_label" not in back.coords
    assert float(back.value.sel(scene="s2", quantity="c")) == 5.0
    assert back.quantity.attrs == {"long_name": "quantity"}


def _disk_with(free_bytes):
    """A stand-in for shutil.disk_usage reporting ``free_bytes`` free."""
    total = 1 << 40
    return lambda path: netcdf.shutil._ntuple_diskusage(total, total - free_bytes, free_bytes)


def _write(ds, path):
    return netcdf.write_dataset(ds, path, scene={}, interpretation="test", method={})


def test_a_full_disk_is_named_before_anything_is_written(tmp_path, monkeypatch):
    ds = xr.Dataset({"x": ("time", np.arange(1000.0))})
    monkeypatch.setattr(netcdf.shutil, "disk_usage", _disk_with(4096))
    with pytest.raises(OSError, match="no space left on device") as info:
        _write(ds, tmp_path / "a.nc")
    assert isinstance(info.value, netcdf.DiskFullError) and info.value.errno == netcdf.errno.ENOSPC
    assert "a.nc" in str(info.value) and list(tmp_path.iterdir()) == []


def test_the_size_estimate_bounds_the_written_file_and_the_message_states_it_and_the_floor(
    tmp_path, monkeypatch
):
    """Many small variables with long attributes: the file is far larger than the data (HDF5 structure)."""
    ds = xr.Dataset(
        {f"v{i}": ("t", np.arange(10.0), {"comment": "x" * 500}) for i in range(60)},
        attrs={"note": "y" * 5000},
    )
    path = _write(ds, tmp_path / "many.nc")
    assert netcdf.estimated_file_bytes(ds) >= path.stat().st_size > 10 * ds.nbytes
    monkeypatch.setattr(netcdf.shutil, "disk_usage", _disk_with(2 << 20))
    big = ds.assign(big=("n", np.zeros(400_000)))  # 3.2 MB of data, 2 MiB free
    needed = netcdf.estimated_file_bytes(big)
    with pytest.raises(netcdf.DiskFullError, match=r"needs an estimated \d+ bytes.*at least 1048576") as info:
        _write(big, tmp_path / "b.nc")
    stated = int(re.search(r"estimated (\d+) bytes", str(info.value))[1])
    assert needed <= stated < needed + 20_000  # plus the provenance attributes the writer adds


def test_a_write_that_fails_on_a_disk_that_filled_up_is_named_and_leaves_nothing(tmp_path, monkeypatch):
    """The netCDF library reports ENOSPC as 'NetCDF: HDF error': the free space decides what it was."""
    ds = xr.Dataset({"x": ("time", np.arange(1000.0))})
    calls = []

    def filling(path):  # room before the write, none once it has started
        calls.append(path)
        return _disk_with(1 << 30 if len(calls) == 1 else 0)(path)

    def hdf_error(self, *args, **kwargs):
        raise RuntimeError("NetCDF: HDF error")

    monkeypatch.setattr(netcdf.shutil, "disk_usage", filling)
    monkeypatch.setattr(xr.Dataset, "to_netcdf", hdf_error)
    with pytest.raises(OSError, match="no space left on device"):
        _write(ds, tmp_path / "a.nc")
    assert list(tmp_path.iterdir()) == []
    # the same library error with room to spare is not called a full disk
    monkeypatch.setattr(netcdf.shutil, "disk_usage", _disk_with(1 << 30))
    with pytest.raises(RuntimeError, match="HDF error"):
        _write(ds, tmp_path / "a.nc")
    assert list(tmp_path.iterdir()) == []
