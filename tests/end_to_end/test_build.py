"""`make figures` heals its folder (stickslip.pipeline.build): a deleted or damaged result is rebuilt, a
killed build is recovered from without a flag, and a second build in the same folder is refused."""

import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

from stickslip.pipeline import integrity

from project_run import (
    SLOW_TARGET,
    copy_project,
    run_snakemake,
    shared_small_run,
    slow_fe_project,
    small_config_args,
    snakemake_command,
)


def flip_a_byte_keeping_mtime(path):
    st = os.stat(path)
    data = bytearray(path.read_bytes())
    data[len(data) // 2] ^= 0xFF
    path.write_bytes(bytes(data))
    os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns))


def test_the_record_finds_a_flipped_byte_with_its_mtime_kept_and_a_missing_file(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    results = tmp_path / "results"
    for name in ("a.nc", "b.csv", "c.inp", "logs/job.log"):
        (results / name).parent.mkdir(parents=True, exist_ok=True)
        (results / name).write_bytes(os.urandom(4096))
    integrity.record(integrity.Path("results"), time.time_ns(), {})
    assert integrity.damaged() == ([], integrity.load())
    assert "results/logs/job.log" not in integrity.load()  # a log is no result

    flip_a_byte_keeping_mtime(results / "a.nc")
    (results / "b.csv").unlink()
    (results / "c.inp").touch()  # a new stat, the same bytes: not damaged
    bad, entries = integrity.damaged()
    assert bad == ["results/a.nc", "results/b.csv"]
    assert entries["results/c.inp"]["stat"] == integrity._stat_key(os.stat("results/c.inp"))


def build_command(work, *args):
    """`make figures` on a project copy: the build wrapper around the small configuration's snakemake."""
    return [sys.executable, "-m", "stickslip.pipeline.build", *snakemake_command(work, *args)]


def build(work, *args, timeout=1200):
    proc = subprocess.run(
        build_command(work, *args), cwd=work, capture_output=True, text=True, timeout=timeout
    )
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return proc.stdout + proc.stderr


@pytest.mark.pipeline
def test_a_deleted_intermediate_and_a_flipped_byte_with_mtime_kept_are_rebuilt_identically(
    tmp_path_factory, tmp_path
):
    source = shared_small_run(tmp_path_factory)
    work = tmp_path / "project"
    shutil.copytree(source, work, symlinks=True)
    args = small_config_args(work)
    assert "Nothing to be done" in build(work, *args)  # the first wrapped build records the results

    # neither is a rule-all input of the final products: a claim's run and a figure's run of another reading
    flipped = work / "results/onedof/fig06/consistent_caption/exact.nc"
    deleted = work / "results/onedof/fig05/eq3_text/exact.nc"
    flip_a_byte_keeping_mtime(flipped)
    deleted.unlink()
    out = build(work, *args)
    assert "rebuilding" in out and "fig06/consistent_caption/exact.nc" in out, out[-3000:]
    assert deleted.exists()
    cmd = [sys.executable, "-m", "stickslip.io.compare", str(source / "results"), str(work / "results")]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-2000:]
    assert "Nothing to be done" in build(work, *args)


TARGET = SLOW_TARGET


@pytest.mark.pipeline
def test_a_second_build_is_refused_and_a_killed_build_recovers_without_a_flag(tmp_path):
    work, args = slow_fe_project(tmp_path)

    log = open(tmp_path / "killed.log", "w")
    proc = subprocess.Popen(
        build_command(work, TARGET, *args),
        cwd=work,
        stdout=log,
        stderr=subprocess.STDOUT,
        start_new_session=True,
    )
    job_log = work / "results" / "logs" / "fe_reading" / "lower_face_drop.log"
    deadline = time.monotonic() + 120
    while not job_log.exists() and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.2)
    time.sleep(1.0)
    assert proc.poll() is None, (
        "the job finished before it could be killed: make the slow scene longer (project_run.slow_fe_project)"
    )

    second = subprocess.run(build_command(work, TARGET, *args), cwd=work, capture_output=True, text=True)
    assert second.returncode == 1
    assert "another build is running in this folder" in second.stderr, second.stderr[-2000:]

    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait(timeout=30)
    assert not (work / TARGET).exists()
    build(work, TARGET, *args)  # no --unlock, no --rerun-incomplete
    assert (work / TARGET).exists()


@pytest.mark.pipeline
def test_a_build_of_another_configuration_is_refused_before_any_job_and_leaves_the_results_untouched(
    tmp_path,
):
    work = copy_project(tmp_path)
    table = "results/onedof/friction_mu_vr.csv"
    run_snakemake(work, table)  # the full configuration's build owns results/
    before = {
        p: p.read_bytes() for p in (work / "results").rglob("*") if p.is_file() and "logs" not in p.parts
    }

    small = run_snakemake(
        work, "--forcerun", "friction_table", *small_config_args(work), "--", table, check=False
    )
    assert small.returncode == 1
    assert "results/ holds the build of configuration config/*.yaml; this build is config/*.yaml + " in (
        small.stdout + small.stderr
    )
    assert "make small" in small.stdout + small.stderr
    after = {
        p: p.read_bytes() for p in (work / "results").rglob("*") if p.is_file() and "logs" not in p.parts
    }
    assert after == before
    run_snakemake(
        work, "--forcerun", "friction_table", "--", table
    )  # the owner's own configuration still builds
