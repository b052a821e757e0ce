"""The progress callback: done/total, elapsed and a linear ETA, at most one line every N seconds."""

from stickslip.io.progress import Progress, format_seconds


class Clock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


def test_lines_are_throttled_and_eta_is_linear():
    clock, lines = Clock(), []
    progress = Progress("sweep", every=5.0, sink=lines.append, clock=clock)
    progress(0, 10)  # the clock starts at the first call
    for done in range(1, 5):  # 1 s per unit: first line only once 5 s have passed
        clock.now += 1.0
        progress(done, 10)
    assert lines == []
    clock.now += 1.0
    progress(5, 10)
    assert lines == ["sweep: 5/10 (50.0 %), elapsed 5.0 s, ETA 5.0 s"]
    for done in range(6, 11):
        clock.now += 1.0
        progress(done, 10)
    assert lines[-1] == "sweep: 10/10 (100.0 %), elapsed 10.0 s, ETA 0.0 s"  # the last unit always logs
    assert progress.lines == lines and len(lines) == 2


def test_format_seconds():
    assert format_seconds(float("nan")) == "unknown"
    assert format_seconds(185) == "3 min 05 s"
    assert format_seconds(3720) == "1 h 02 min"


def test_time_steps_are_reported_with_an_estimate():
    lines = []
    report = Progress("fe", every=0.0, sink=lines.append)
    for done in (10_000, 20_000, 40_000):
        report(done, 40_000)
    assert lines and "40000/40000" in lines[-1].replace(" ", "").replace(",", "")
