"""Progress of long loops with an estimate of the remaining time, logged at most every few seconds.

Use in a long-running pipeline script (FE scenes, dense sweeps)::

    from stickslip.io.progress import Progress

    progress = Progress(len(values), label="penalty_sweep", every=10.0)
    for value in values:
        run(value)
        progress.advance()          # logs "penalty_sweep: 3/8 (37.5 %), elapsed 12.0 s, ETA 20.0 s"
    progress.finish()

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
    """Counts ``done`` out of ``total`` units of work and reports ``done/total, elapsed, ETA``.

    A line is emitted on the first call after ``every`` seconds have passed since the last line (and always
    for the last unit), so a tight loop may call :meth:`advance` on every step at negligible cost.
    ``clock`` is injectable for tests.
    """

    def __init__(
        self,
        total: int,
        *,
        label: str = "progress",
        every: float = 10.0,
        sink: Callable[[str], None] | None = None,
        clock: Callable[[], float] = time.monotonic,
    ):
        if total < 0:
            raise ValueError(f"total: must be >= 0, got {total!r}")
        self.total = int(total)
        self.label = label
        self.every = float(every)
        self.sink = sink
        self.clock = clock
        self.done = 0
        self.start = clock()
        self._last = self.start
        self.lines: list[str] = []

    @property
    def elapsed(self) -> float:
        return self.clock() - self.start

    def eta(self) -> float:
        """Seconds left, linear in the work done so far; NaN before the first unit is done."""
        if self.done <= 0:
            return float("nan")
        return self.elapsed / self.done * max(self.total - self.done, 0)

    def message(self) -> str:
        pct = 100.0 * self.done / self.total if self.total else 100.0
        return (
            f"{self.label}: {self.done}/{self.total} ({pct:.1f} %), elapsed {format_seconds(self.elapsed)}, "
            f"ETA {format_seconds(self.eta())}"
        )

    def _emit(self) -> None:
        line = self.message()
        self.lines.append(line)
        if self.sink is not None:
            self.sink(line)
        else:
            LOGGER.info(line)
        self._last = self.clock()

    def advance(self, n: int = 1) -> None:
        self.done = min(self.done + n, self.total) if self.total else self.done + n
        if self.done >= self.total or self.clock() - self._last >= self.every:
            self._emit()

    def update(self, done: int) -> None:
        """Set the absolute count (for loops that know their position)."""
        self.advance(int(done) - self.done)

    def finish(self) -> None:
        """Log the final line if the last :meth:`advance` did not."""
        if not self.lines or self.lines[-1] != self.message():
            self._emit()


def step_callback(label: str, every: float = 10.0, sink: Callable[[str], None] | None = None):
    """A ``progress(done, total)`` callback for loops that report their own position (e.g. FE time steps).

    The :class:`Progress` is created on the first call, when the total is known.
    """
    state: dict = {}

    def report(done: int, total: int) -> None:
        if "progress" not in state:
            state["progress"] = Progress(total, label=label, every=every, sink=sink)
        state["progress"].update(done)

    return report


def log_to_file(path, capture_output: bool = False) -> None:
    """Send this process's log records (INFO and up, time-stamped) to ``path``: a job's log file. With
    ``capture_output`` printed output and warnings go there too (line-buffered)."""
    import logging
    import sys

    stream = open(path, "w", buffering=1)  # noqa: SIM115 - stays open for the life of the job
    if capture_output:
        sys.stdout = sys.stderr = stream
    logging.basicConfig(stream=stream, level=logging.INFO, format="%(asctime)s %(message)s", force=True)
