"""Two clean runs of the small configuration give bit-identical data arrays (attributes aside: history and
source carry timestamps and the git revision)."""

import pytest

from project_run import (
    copy_project,
    data_differences_in_subprocess,
    datasets,
    run_snakemake,
    shared_small_run,
    small_config_args,
)


@pytest.mark.pipeline
def test_two_clean_runs_are_bit_identical(tmp_path_factory):
    first = shared_small_run(tmp_path_factory)
    second = copy_project(tmp_path_factory.mktemp("second_run"))
    targets = [
        f"results/{p}" for p in datasets(first)
    ]  # only the data: figures and notebooks are not compared
    run_snakemake(second, *targets, *small_config_args(second))  # targets first: --configfile takes a list
    assert datasets(second) == datasets(first)
    diffs = data_differences_in_subprocess(first / "results", second / "results", datasets(first))
    diffs = {p: d for p, d in diffs.items() if d}
    assert not diffs, diffs
