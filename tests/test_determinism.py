"""Two clean runs of the small configuration give bit-identical data arrays (attributes aside: history and
source carry timestamps and the git revision).

The second run builds one dataset of every rule that writes datasets (with whatever that job needs), not the
whole configuration: every rule's code runs twice from nothing, at a third of the cost. Rules downstream of
the claims table are left out (the table reads every claimed dataset, so they would rebuild everything)."""

from pathlib import PurePath

import pytest

from project_run import (
    copy_project,
    data_differences_in_subprocess,
    datasets,
    run_snakemake,
    shared_small_run,
    small_config_args,
)


def one_dataset_per_rule(workdir) -> dict[str, str]:
    """rule -> the first (sorted) dataset it wrote, from Snakemake's own record of the run (--summary)."""
    proc = run_snakemake(workdir, *small_config_args(workdir), "--summary")
    outputs: dict[str, list[str]] = {}
    for line in proc.stdout.splitlines()[1:]:
        path, _, rule, *_ = line.split("\t")
        if path.endswith(".nc") and not path.startswith("results/claims/"):
            outputs.setdefault(rule, []).append(path)
    kept = {rule: [p for p in sorted(paths) if (workdir / p).exists()] for rule, paths in outputs.items()}
    return {rule: paths[0] for rule, paths in sorted(kept.items()) if paths}  # temp() outputs are gone


@pytest.mark.pipeline
def test_one_job_of_every_rule_rebuilt_from_nothing_is_bit_identical(tmp_path_factory):
    first = shared_small_run(tmp_path_factory)
    targets = one_dataset_per_rule(first)
    assert {"simulate_onedof_fig02", "onedof_sweeps", "fe_reading", "methods_work_precision"} <= set(targets)
    second = copy_project(tmp_path_factory.mktemp("second_run"))
    # the targets first: --configfile takes every argument after it
    run_snakemake(second, *targets.values(), *small_config_args(second))
    rebuilt = datasets(second)
    assert {PurePath(t).relative_to("results") for t in targets.values()} <= set(rebuilt)
    assert set(rebuilt) <= set(datasets(first))
    diffs = data_differences_in_subprocess(first / "results", second / "results", rebuilt)
    diffs = {p: d for p, d in diffs.items() if d}
    assert not diffs, diffs
