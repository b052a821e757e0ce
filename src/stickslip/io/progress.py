"""Progress of long loops with an estimate of the remaining time, logged at most every few seconds.

A loop that knows its position reports it to a ``Progress`` (a dense-map chunk's runs, FE time steps)::

    report = Progress("map fig07 chunk 3", every=5.0)
    for done in range(1, total + 1):
        run(done)
        report(done, total)         # logs "map fig07 chunk 3: 3/8 (37.5 %), elapsed 12.0 s, ETA 20.0 s"

Each line goes to the ``stickslip.progress`` logger (INFO), so it lands in the rule's log file when the
script configures logging to ``snakemake.log[0]``; a ``sink`` callable (e.g. ``print``) may be given instead.
The estimate is linear in the completed work (elapsed / done * remaining): right for fixed-step integrators
and sweeps of similar runs, which is what the pipeline's long rules are.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable

LOGGER = logging.getLogger("stickslip.progress")


def format_seconds(seconds: float) -> str:
    """``42.0 s``, ``3 min 05 s``, ``1 h 02 min``: short enough for a log line."""
    if seconds != seconds or seconds == float("inf"):  # NaN or unknown
        return "unknown"
    seconds = max(0.0, float(seconds))
    if seconds < 60:
        return f"{seconds:.1f} s"
    minutes, sec = divmod(int(round(seconds)), 60)
    if minutes < 60:
        return f"{minutes} min {sec:02d} s"
    hours, minutes = divmod(minutes, 60)
    return f"{hours} h {minutes:02d} min"


class Progress:
    """A ``progress(done, total)`` callback: logs ``label: done/total (pct %), elapsed, ETA`` on the first
    call after ``every`` seconds have passed since its last line (and always for the last unit), so a tight
    loop may call it on every step at negligible cost. The clock starts at the first call; ``clock`` is
    injectable for tests, and ``lines`` keeps every line logged."""

    def __init__(
        self,
        label: str,
        every: float = 10.0,
        sink: Callable[[str], None] | None = None,
        clock: Callable[[], float] = time.monotonic,
    ):
        self.label, self.every, self.sink, self.clock = label, float(every), sink, clock
        self.start: float | None = None
        self.lines: list[str] = []

    def __call__(self, done: int, total: int) -> None:
        if total < 0:
            raise ValueError(f"total: must be >= 0, got {total!r}")
        if self.start is None:
            self.start = self._last = self.clock()
        done = min(int(done), total) if total else int(done)
        if done < total and self.clock() - self._last < self.every:
            return
        elapsed = self.clock() - self.start
        eta = elapsed / done * max(total - done, 0) if done > 0 else float("nan")  # linear in the work done
        pct = 100.0 * done / total if total else 100.0
        line = (
            f"{self.label}: {done}/{total} ({pct:.1f} %), elapsed {format_seconds(elapsed)}, "
            f"ETA {format_seconds(eta)}"
        )
        self.lines.append(line)
        (self.sink or LOGGER.info)(line)
        self._last = self.clock()


def log_to_file(path, capture_output: bool = False) -> None:
    """Send this process's log records (INFO and up, time-stamped) to ``path``: a job's log file. With
    ``capture_output`` printed output and warnings go there too (line-buffered)."""
    import sys

    stream = open(path, "w", buffering=1)  # noqa: SIM115 - stays open for the life of the job
    if capture_output:
        sys.stdout = sys.stderr = stream
    logging.basicConfig(stream=stream, level=logging.INFO, format="%(asctime)s %(message)s", force=True)
