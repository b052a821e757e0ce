"""Snakemake logger plugin ``stickslip-progress``: one console line per finished job, with an estimate.

    snakemake --logger stickslip-progress ...        (``make figures`` passes it)

    [12/66 done, 18 %] rule fe_reading (fe_reading=lower_face_drop) 31 s — about 4 min left

The plugin takes the console's place (``writes_to_stream``: Snakemake then adds no console handler of its
own) and keeps Snakemake's filter and formatter (``has_filter``/``has_formatter`` False: Snakemake attaches
its defaults). Every record it does not summarise goes to Snakemake's own console handler, so errors,
warnings, the job table and the closing summary read as without the plugin. Replaced by the one line: a
job's "rule ...: input, output ..." block, "Execute n jobs...", "Finished jobid ...", "n of m steps" and
"Select jobs to execute...".
A dry run shows the blocks as usual (nothing finishes there).

The estimate: with the benchmark files of a previous build (``results/benchmarks/<rule>/*.tsv``, the
first folder naming the rule or the family of rules a loop makes, e.g. ``simulate_onedof`` for
``simulate_onedof_fig02``), the typical (median) seconds of each rule times the jobs of it still to run,
less what the running ones have done, over the cores; without them, the time so far per job done times the
jobs left. It lives under ``src/`` as a package of its own (found by Snakemake by its module name through
the editable install) and imports nothing of ``stickslip``: the console never waits for the science.
"""

from __future__ import annotations

import csv
import logging
import statistics
import sys
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from snakemake_interface_logger_plugins.base import LogHandlerBase
from snakemake_interface_logger_plugins.common import LogEvent

from stickslip.catalogue import benchmarks_folder

#: where a previous build's ``benchmark:`` files are, relative to the working directory
BENCHMARKS = Path(benchmarks_folder())

#: the per-job records the one line replaces (a dry run keeps them)
REPLACED = {LogEvent.JOB_INFO, LogEvent.JOB_STARTED, LogEvent.JOB_FINISHED, LogEvent.PROGRESS}
#: plain messages of every scheduling round, which say nothing the line does not
ROUND_MESSAGES = {"Select jobs to execute..."}


def typical_seconds(root: Path) -> dict[str, float]:
    """Benchmark folder (the first below ``root``) -> the median wall time ``s`` of its jobs."""
    seconds: dict[str, list[float]] = {}
    for path in sorted(root.rglob("*.tsv")) if root.is_dir() else []:
        try:
            with path.open(newline="") as fh:
                rows = [float(r["s"]) for r in csv.DictReader(fh, delimiter="\t") if r.get("s")]
        except (OSError, ValueError, KeyError):
            continue  # a half-written or foreign file estimates nothing
        seconds.setdefault(path.relative_to(root).parts[0].removesuffix(".tsv"), []).extend(rows)
    return {folder: statistics.median(s) for folder, s in seconds.items() if s}


def human(seconds: float) -> str:
    """A duration as a person says it: '31 s', '4 min', '1.5 h'."""
    if seconds < 120:
        return f"{int(seconds + 0.5)} s"
    if seconds < 120 * 60:
        return f"{int(seconds / 60 + 0.5)} min"
    return f"{seconds / 3600:.1f} h"


@dataclass
class Job:
    rule: str
    wildcards: dict
    started: float


@dataclass
class Progress:
    """What the console line needs: the jobs planned per rule, when each started, which finished. Times are
    passed in (``now``), so the arithmetic is testable without a clock."""

    typical: dict[str, float] = field(default_factory=dict)  #: benchmark folder -> typical seconds
    started: float = 0.0
    cores: int = 1
    planned: Counter = field(default_factory=Counter)  #: rule -> jobs in this run
    jobs: dict[int, Job] = field(default_factory=dict)
    running: set[int] = field(default_factory=set)
    finished: Counter = field(default_factory=Counter)
    durations: dict[str, list[float]] = field(default_factory=dict)
    waiting: list[int] = field(default_factory=list)  #: finished, its line not yet printed

    def job_info(self, jobid: int, rule: str, wildcards: dict | None, now: float) -> None:
        self.jobs[jobid] = Job(rule, dict(wildcards or {}), now)
        self.running.add(jobid)

    def job_finished(self, jobid: int, now: float) -> None:
        job = self.jobs.setdefault(jobid, Job(f"job {jobid}", {}, now))
        self.running.discard(jobid)
        self.finished[job.rule] += 1
        self.durations.setdefault(job.rule, []).append(now - job.started)
        self.waiting.append(jobid)

    def seconds_for(self, rule: str, fallback: float | None = None) -> float | None:
        """A job of ``rule``'s typical seconds: its benchmark folder's, else this run's mean for the rule,
        else ``fallback``."""
        folders = [f for f in self.typical if rule == f or rule.startswith(f + "_")]
        if folders:
            return self.typical[max(folders, key=len)]
        seen = self.durations.get(rule)
        return statistics.mean(seen) if seen else fallback

    def seconds_left(self, done: int, total: int, now: float) -> float:
        if not self.typical or not self.planned:
            return (now - self.started) / done * (total - done) if done else 0.0
        fallback = statistics.median(self.typical.values())
        work = 0.0
        for rule, count in self.planned.items():
            left = count - self.finished[rule]
            if left > 0:
                work += left * self.seconds_for(rule, fallback)
        for jobid in self.running:  # what the running jobs have done already
            job = self.jobs[jobid]
            work -= min(now - job.started, self.seconds_for(job.rule, fallback))
        return max(work, 0.0) / max(self.cores, 1)

    def lines(self, done: int, total: int, now: float) -> list[str]:
        """One line per job finished since the last call, with ``done`` of ``total`` jobs done."""
        percent = 100 * done // total if total else 100
        head = f"[{done}/{total} done, {percent} %]"
        tail = (
            f"all done in {human(now - self.started)}"
            if done >= total
            else f"about {human(self.seconds_left(done, total, now))} left"
        )
        out = []
        for jobid in self.waiting:
            job = self.jobs[jobid]
            wildcards = ", ".join(f"{k}={v}" for k, v in job.wildcards.items())
            what = f"rule {job.rule}" + (f" ({wildcards})" if wildcards else "")
            out.append(f"{head} {what} {human(now - job.started)} — {tail}")
        self.waiting.clear()
        return out


class LogHandler(LogHandlerBase):
    """The console: one line per finished job, every other record as Snakemake prints it."""

    def __post_init__(self) -> None:
        from snakemake.logging import ColorizingTextHandler

        stream = sys.stdout if getattr(self.common_settings, "stdout", False) else sys.stderr
        #: Snakemake's own console handler, for every record the one line does not replace
        self.console = ColorizingTextHandler(nocolor=bool(self.common_settings.nocolor), stream=stream)
        self.progress = Progress(started=time.monotonic())
        self.clock = time.monotonic

    @property
    def writes_to_stream(self) -> bool:
        return True  # replaces Snakemake's console handler (which would print every job's block)

    @property
    def writes_to_file(self) -> bool:
        return False

    @property
    def has_filter(self) -> bool:
        return False  # Snakemake's filter: --quiet, --printshellcmds, --verbose keep their meaning

    @property
    def has_formatter(self) -> bool:
        return False  # Snakemake's formatter, for the records passed on to its console handler

    @property
    def needs_rulegraph(self) -> bool:
        return False

    def emit(self, record: logging.LogRecord) -> None:
        try:
            self._handle(record)
        except Exception:
            self.handleError(record)

    def _handle(self, record: logging.LogRecord) -> None:
        event = getattr(record, "event", None)
        now = self.clock()
        p = self.progress
        if event == LogEvent.RUN_INFO and isinstance(getattr(record, "stats", None), dict):
            p.planned = Counter({k: int(v) for k, v in record.stats.items() if k != "total"})
            p.typical = typical_seconds(BENCHMARKS)
        elif event == LogEvent.RESOURCES_INFO and getattr(record, "cores", None):
            p.cores = int(record.cores)
        if event is None and record.getMessage() in ROUND_MESSAGES:
            return
        if self.common_settings.dryrun or event not in REPLACED:
            self._pass_on(record)
        elif event == LogEvent.JOB_INFO:
            p.job_info(int(record.jobid), str(record.rule_name), getattr(record, "wildcards", None), now)
        elif event == LogEvent.JOB_FINISHED:
            p.job_finished(int(record.job_id), now)
        elif event == LogEvent.PROGRESS:
            for line in p.lines(int(record.done), int(record.total), now):
                self.write(line)

    def _pass_on(self, record: logging.LogRecord) -> None:
        if self.console.formatter is not self.formatter:  # Snakemake attaches it after construction
            self.console.setFormatter(self.formatter)
        self.console.emit(record)

    def write(self, line: str) -> None:
        self.console.stream.write(line + "\n")
        self.console.flush()
