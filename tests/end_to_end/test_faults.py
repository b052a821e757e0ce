"""Faults: a job killed mid-way leaves no dataset; the rerun completes and matches an uninterrupted run.

The killed run is Snakemake plus its job, SIGKILLed as a process group while an FE scene integrates (the
harshest case: nothing gets to clean up). Recovery, as the README documents it::

    snakemake --unlock && snakemake -j2 --rerun-incomplete
"""

import os
import shutil
import signal
import time

import pytest

from stickslip.io.compare import data_differences

from project_run import SLOW_TARGET, run_snakemake, slow_fe_project, start_snakemake

TARGET = SLOW_TARGET


@pytest.mark.pipeline
def test_killed_job_leaves_no_dataset_and_rerun_matches(tmp_path):
    work, args = slow_fe_project(tmp_path)

    proc = start_snakemake(work, TARGET, *args, log=tmp_path / "killed.log")
    job_log = work / "results" / "logs" / "fe_reading" / "lower_face_drop.log"
    deadline = time.monotonic() + 120
    while not job_log.exists() and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.2)
    time.sleep(2.0)  # the job is now integrating
    assert proc.poll() is None, (
        "the job finished before it could be killed: make the slow scene longer (project_run.slow_fe_project)"
    )
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait(timeout=30)

    assert not (work / TARGET).exists(), "a partial dataset survived the kill"
    fe_results = work / "results" / "fe"
    leftovers = [p.name for p in fe_results.rglob("*.nc")] if fe_results.exists() else []
    assert not [n for n in leftovers if not n.startswith(".")], leftovers  # hidden: unfinished temporaries

    run_snakemake(work, "--unlock", *args)
    run_snakemake(work, TARGET, "--rerun-incomplete", *args)
    assert (work / TARGET).exists()

    # the uninterrupted run of the same job, for comparison
    shutil.move(work / TARGET, tmp_path / "after_kill.nc")
    run_snakemake(work, TARGET, *args)
    assert data_differences(tmp_path / "after_kill.nc", work / TARGET) == []
