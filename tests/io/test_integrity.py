"""A damaged dataset is an error naming the file, never a number: bit flips and truncation are detected."""

import struct

import numpy as np
import pytest
import xarray as xr

from stickslip.io.netcdf import CHECKSUM_ATTR, CorruptDatasetError, main, read_dataset, write_dataset

VALUE = 1.0545


def _write(path):
    ds = xr.Dataset(
        {
            "max_displacement": ((), VALUE, {"units": "mm"}),
            "x": (("time",), np.linspace(0.0, 1.0, 50), {"units": "mm"}),
        },
        coords={"time": ("time", np.arange(50) * 0.1, {"units": "s"})},
    )
    return write_dataset(ds, path, scene={"mass": 1.0}, interpretation="test", method={"name": "exact"})


def test_a_written_dataset_carries_its_checksum_and_reads_back_unchanged(tmp_path):
    path = _write(tmp_path / "a.nc")
    ds = read_dataset(path)
    assert ds.attrs[CHECKSUM_ATTR].startswith("sha256:")
    assert float(ds["max_displacement"]) == VALUE


def test_a_same_size_bit_flip_in_a_scalar_is_detected_and_names_the_file(tmp_path):
    path = _write(tmp_path / "a.nc")
    data = bytearray(path.read_bytes())
    where = data.find(struct.pack("<d", VALUE))
    assert where >= 0, "the scalar's bytes are stored uncompressed"
    data[where + 5] ^= 0x01  # the value moves in its 9th significant digit: still a plausible number
    path.write_bytes(bytes(data))
    with xr.open_dataset(path) as raw:  # what a reader without the check would take as the result
        assert float(raw["max_displacement"]) != VALUE
    with pytest.raises(CorruptDatasetError, match=r"a\.nc.*no longer matches.*make repair"):
        read_dataset(path)


def test_a_truncated_dataset_is_an_error_naming_the_file(tmp_path):
    path = _write(tmp_path / "a.nc")
    path.write_bytes(path.read_bytes()[: path.stat().st_size // 2])
    with pytest.raises(CorruptDatasetError, match=r"a\.nc.*cannot be read.*make repair"):
        read_dataset(path)


def test_a_dataset_written_without_the_checksum_is_refused(tmp_path):
    path = tmp_path / "plain.nc"
    xr.Dataset({"v": ((), 1.0)}).to_netcdf(path)
    with pytest.raises(CorruptDatasetError, match="no content checksum"):
        read_dataset(path)


def test_verify_lists_exactly_the_damaged_datasets(tmp_path, capsys):
    good, bad = _write(tmp_path / "good.nc"), _write(tmp_path / "sub" / "bad.nc")
    bad.write_bytes(bad.read_bytes()[:100])
    assert main(["verify", str(tmp_path)]) == 1
    assert capsys.readouterr().out.split() == [str(bad)]
    bad.unlink()
    assert main(["verify", str(tmp_path)]) == 0 and good.exists()
