"""The console's one line per finished job (Snakemake logger plugin ``stickslip-progress``): its counts and
estimate from synthetic records, and a real Snakemake run that prints it, errors included."""

import io
import logging
import re
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest
from snakemake.logging import DefaultFormatter
from snakemake_interface_logger_plugins.common import LogEvent

import snakemake_logger_plugin_stickslip_progress as plugin

LINE = re.compile(r"^\[(\d+)/(\d+) done, (\d+) %\] rule (\w+)(?: \((.*)\))? (\d+) (?:s|min|h) — (.*)$")


class Clock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


def _handler(dryrun=False):
    settings = SimpleNamespace(
        printshellcmds=False, nocolor=True, quiet=None, debug_dag=False, verbose=False,
        show_failed_logs=False, stdout=False, dryrun=dryrun,
    )  # fmt: skip
    handler = plugin.LogHandler(settings, None)
    handler.setFormatter(DefaultFormatter())
    handler.console.setStream(io.StringIO())
    handler.clock = Clock()
    handler.progress.started = 0.0
    return handler


def _record(event, msg="", level=logging.INFO, **extra):
    record = logging.LogRecord("snakemake", level, "workflow.py", 1, msg, None, None)
    record.event = event
    record.__dict__.update(extra)
    return record


def _feed(handler, t, event, **extra):
    handler.clock.now = t
    handler.emit(_record(event, **extra))


def _plan(handler, cores=1):
    _feed(handler, 0, LogEvent.RESOURCES_INFO, msg=f"Provided cores: {cores}", cores=cores)
    _feed(handler, 0, LogEvent.RUN_INFO, msg="Job stats: ...", stats={"sim": 2, "plot": 1, "total": 3})


def _printed(handler) -> list[str]:
    return handler.console.stream.getvalue().splitlines()


def test_a_finished_job_prints_its_counts_duration_and_the_time_left_from_the_time_so_far(
    tmp_path, monkeypatch
):
    monkeypatch.chdir(tmp_path)  # no benchmarks of a previous build here
    handler = _handler()
    _plan(handler)
    _feed(handler, 0, LogEvent.JOB_INFO, jobid=7, rule_name="sim", wildcards={"scene": "fig02"})
    _feed(handler, 0, LogEvent.JOB_STARTED, msg="Execute 1 jobs...", jobs=[7])
    _feed(handler, 30, LogEvent.JOB_FINISHED, job_id=7)
    assert _printed(handler)[-1] == "Job stats: ..."  # nothing until Snakemake counts the job done
    _feed(handler, 30, LogEvent.PROGRESS, done=1, total=3)
    line = _printed(handler)[-1]
    assert line == "[1/3 done, 33 %] rule sim (scene=fig02) 30 s — about 60 s left"  # 30 s a job, 2 to go
    assert LINE.match(line).group(1, 2, 3, 4, 5, 6) == ("1", "3", "33", "sim", "scene=fig02", "30")

    _feed(handler, 30, LogEvent.JOB_INFO, jobid=8, rule_name="sim", wildcards={"scene": "fig05"})
    _feed(handler, 50, LogEvent.JOB_FINISHED, job_id=8)
    _feed(handler, 50, LogEvent.PROGRESS, done=2, total=3)
    assert _printed(handler)[-1] == "[2/3 done, 66 %] rule sim (scene=fig05) 20 s — about 25 s left"
    _feed(handler, 50, LogEvent.JOB_INFO, jobid=9, rule_name="plot", wildcards={})
    _feed(handler, 230, LogEvent.JOB_FINISHED, job_id=9)
    _feed(handler, 230, LogEvent.PROGRESS, done=3, total=3)
    assert _printed(handler)[-1] == "[3/3 done, 100 %] rule plot 3 min — all done in 4 min"
    assert len([line for line in _printed(handler) if LINE.match(line)]) == 3
    assert not any("Execute" in line or "Rule:" in line for line in _printed(handler))


def test_the_time_left_uses_a_previous_builds_benchmarks_per_rule(tmp_path, monkeypatch):
    """Typical seconds per rule (median of its benchmark files; a loop's rules share their family's folder)
    times the jobs left, less the running jobs' time so far, over the cores."""
    for path, seconds in {
        "sim/fig02.tsv": 100,
        "sim/fig05.tsv": 140,
        "sim/fig06.tsv": 120,
        "plot/all.tsv": 40,
    }.items():
        (tmp_path / "results/benchmarks" / path).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "results/benchmarks" / path).write_text(f"s\th:m:s\n{seconds}\t0:00:00\n")
    monkeypatch.chdir(tmp_path)
    handler = _handler()
    _feed(handler, 0, LogEvent.RESOURCES_INFO, msg="Provided cores: 2", cores=2)
    _feed(handler, 0, LogEvent.RUN_INFO, msg="Job stats", stats={"sim_fig02": 1, "sim_fig05": 1, "plot": 2})
    _feed(handler, 0, LogEvent.JOB_INFO, jobid=1, rule_name="sim_fig02", wildcards={})
    _feed(handler, 0, LogEvent.JOB_INFO, jobid=2, rule_name="sim_fig05", wildcards={})
    _feed(handler, 90, LogEvent.JOB_FINISHED, job_id=1)
    _feed(handler, 90, LogEvent.PROGRESS, done=1, total=4)
    # left: sim_fig05 120 s less its 90 s so far, 2 plots x 40 s: 110 s of work on 2 cores
    assert _printed(handler)[-1] == "[1/4 done, 25 %] rule sim_fig02 90 s — about 55 s left"


def test_snakemakes_other_messages_still_reach_the_console(tmp_path):
    handler = _handler()
    _feed(handler, 0, LogEvent.ERROR, msg="MissingInputException: no rule makes x.nc", level=logging.ERROR)
    _feed(handler, 0, None, msg="Select jobs to execute...")
    _feed(handler, 0, None, msg="Nothing to be done.")
    assert _printed(handler) == ["MissingInputException: no rule makes x.nc", "Nothing to be done."]


SNAKEFILE = """\
rule a:
    output: "a.txt"
    shell: "echo a > {output}"

rule b:
    input: "a.txt"
    output: "b.txt"
    shell: "cat {input} > {output}"

rule c:
    input: "b.txt"
    output: "c.txt"
    shell: "test ${{FAIL:-0}} = 0 && cat {input} > {output}"
"""


def _snakemake(folder: Path, *args, env_extra=None) -> subprocess.CompletedProcess:
    import os

    snakemake = Path(sys.executable).with_name("snakemake")
    env = {**os.environ, **(env_extra or {})}
    cmd = [str(snakemake), "c.txt", *args, "-j1", "--logger", "stickslip-progress"]  # --logger takes a list
    return subprocess.run(cmd, cwd=folder, capture_output=True, text=True, timeout=300, env=env)


@pytest.mark.pipeline
def test_a_real_snakemake_run_prints_one_line_per_job_and_still_shows_a_jobs_error(tmp_path):
    (tmp_path / "Snakefile").write_text(SNAKEFILE)
    dry = _snakemake(tmp_path, "-n")  # a dry run keeps the job blocks: nothing finishes there
    shown = dry.stdout + dry.stderr  # (a dry run prints to stdout)
    assert dry.returncode == 0 and "rule a:" in shown and "rule c:" in shown, shown
    proc = _snakemake(tmp_path)
    assert proc.returncode == 0, proc.stderr
    lines = [LINE.match(line) for line in proc.stderr.splitlines()]
    found = [m.group(1, 2, 4) for m in lines if m]
    assert found == [("1", "3", "a"), ("2", "3", "b"), ("3", "3", "c")], proc.stderr
    assert "Finished jobid" not in proc.stderr and "of 3 steps" not in proc.stderr

    (tmp_path / "c.txt").unlink()
    failed = _snakemake(tmp_path, env_extra={"FAIL": "1"})
    assert failed.returncode != 0
    assert "Error in rule c" in failed.stderr and "Exiting because a job execution failed" in failed.stderr
