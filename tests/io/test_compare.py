"""The results comparison (python -m stickslip.io.compare A B) finds every kind of difference."""

import numpy as np
import xarray as xr

from stickslip.io.compare import compare_results, main


def write(root, name, values, cpu=0.0):
    path = root / name
    path.parent.mkdir(parents=True, exist_ok=True)
    xr.Dataset({"x": ("t", np.asarray(values, float)), "cpu_time": ((), cpu)}).to_netcdf(path)


def test_identical_folders_compare_clean_and_cpu_times_are_ignored(tmp_path, capsys):
    for root, cpu in ((tmp_path / "a", 1.0), (tmp_path / "b", 2.0)):
        write(root, "onedof/s.nc", [1.0, np.nan, 3.0], cpu=cpu)
    assert compare_results(tmp_path / "a", tmp_path / "b") == ([], 1)
    assert main([str(tmp_path / "a"), str(tmp_path / "b")]) == 0
    assert "1 files compared: identical" in capsys.readouterr().out


def test_a_last_bit_change_a_missing_file_and_a_changed_claims_table_are_reported(tmp_path):
    write(tmp_path / "a", "onedof/s.nc", [1.0, 2.0])
    write(tmp_path / "b", "onedof/s.nc", [1.0, np.nextafter(2.0, 3.0)])
    write(tmp_path / "a", "fe/only_a.nc", [0.0])
    for root, status in ((tmp_path / "a", "reproduced"), (tmp_path / "b", "deviates")):
        (root / "claims").mkdir()
        (root / "claims" / "deviations.csv").write_text(f"claim,status\nc1,{status}\n")
    lines, compared = compare_results(tmp_path / "a", tmp_path / "b")
    assert compared == 3
    assert lines == [
        f"only in {tmp_path / 'a'}: fe/only_a.nc",
        "claims/deviations.csv: differs",
        "onedof/s.nc: x: 1 values differ",
    ]
    assert main([str(tmp_path / "a"), str(tmp_path / "b")]) == 1


def with_members(root, name, labels, values):
    """A dataset with an ensemble over ``labels``: one value per member of metric ``m``."""
    path = root / name
    path.parent.mkdir(parents=True, exist_ok=True)
    xr.Dataset(
        {"m": ((), values[0]), "m_ensemble": ("ensemble_member", np.asarray(values, float))},
        coords={
            "ensemble_member": np.arange(len(labels), dtype=np.int32),
            "ensemble_member_label": ("ensemble_member", np.array(labels, dtype=object)),
        },
    ).to_netcdf(path)


def test_a_member_added_by_a_change_is_left_out_on_request_and_any_other_change_still_found(tmp_path, capsys):
    with_members(tmp_path / "a", "onedof/s.nc", ["base", "seed0"], [1.0, 1.1])
    with_members(tmp_path / "b", "onedof/s.nc", ["base", "seed0", "window"], [1.0, 1.1, 7.0])
    assert compare_results(tmp_path / "a", tmp_path / "b")[0] != []  # the new member is a difference
    assert compare_results(tmp_path / "a", tmp_path / "b", ("window",)) == ([], 1)
    assert main([str(tmp_path / "a"), str(tmp_path / "b"), "--without-member", "window"]) == 0
    with_members(tmp_path / "b", "onedof/s.nc", ["base", "seed0", "window"], [1.0, 1.2, 7.0])
    lines, _ = compare_results(tmp_path / "a", tmp_path / "b", ("window",))
    assert lines == ["onedof/s.nc: m_ensemble: 1 values differ"]


def test_every_file_a_build_writes_is_compared_but_logs_benchmarks_and_temporaries(tmp_path):
    """Tables, decks and pages are results too (a table ordered by the hash seed differed only there);
    the jobs' logs, Snakemake's benchmark timings and hidden temporaries are not."""
    for root, word in ((tmp_path / "a", "one"), (tmp_path / "b", "two")):
        for name in (
            "claims/unreproduced_claims.csv",
            "fe/inp/deck.inp",
            "page/index.html",
            "logs/job.log",
            "benchmarks/job.tsv",
            "fe/.deck.inp.x.tmp",
            "page/thumbs/.snakemake_timestamp",
        ):
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(f"{name}: {word}\n")
    lines, compared = compare_results(tmp_path / "a", tmp_path / "b")
    assert compared == 3
    assert lines == [
        "claims/unreproduced_claims.csv: differs",
        "fe/inp/deck.inp: differs",
        "page/index.html: differs",
    ]
