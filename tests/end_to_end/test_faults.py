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
import yaml

from stickslip.io.compare import data_differences

from project_run import copy_project, run_snakemake, small_config_args, start_snakemake

SCENE = "section9_kinematic_0p5mm_s"
TARGET = f"results/fe/lower_face_drop/{SCENE}.nc"
# the target scene alone runs long (~6-15 s of integration per ensemble member, by machine) so the kill meets
# it integrating, also where the compiled kernels are fast;
# the reading's other scenes keep the small configuration's 4 ms (the three runs of the job cost their
# slowest scene, not every scene at 1.2 s)
SLOW = {"fe": {"scenes": {SCENE: {"solver": {"t_end": 3.0, "output_dt": 1.0e-3}}}}}


@pytest.mark.pipeline
def test_killed_job_leaves_no_dataset_and_rerun_matches(tmp_path):
    (tmp_path / "project").mkdir()
    work = copy_project(tmp_path / "project")
    slow = work / "slow.yaml"
    slow.write_text(yaml.safe_dump(SLOW))
    args = small_config_args(work, slow)
    run_snakemake(work, "results/onedof/friction_mu_vr.csv", *args)  # the FE scene's input, not under test

    proc = start_snakemake(work, TARGET, *args, log=tmp_path / "killed.log")
    job_log = work / "results" / "logs" / "fe_reading" / "lower_face_drop.log"
    deadline = time.monotonic() + 120
    while not job_log.exists() and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.2)
    time.sleep(2.0)  # the job is now integrating
    assert proc.poll() is None, "the job finished before it could be killed: make SLOW longer"
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
