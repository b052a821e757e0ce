"""Metrics measured from a trajectory: stick/slip intervals, amplitudes, velocities, frequency.

Every metric is a small pure function; ``limit_cycle_metrics`` gathers them into the table stored with each
dataset. Interval lengths come from the solver's exact switching record when it has one, otherwise from
the per-sample phase (then they are only as fine as the sample spacing).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..solvers.base import STICK, Trajectory
from .friction_curve import friction_along_solution
from .outcome import OUTCOMES, REST_FRACTION, outcome_code, run_outcome


@dataclass(frozen=True)
class Metric:
    value: float
    units: str
    long_name: str


@dataclass(frozen=True)
class MetricInfo:
    """What a metric is: its units (UDUNITS) and long name; ``{count_window}`` is filled in per run."""

    units: str
    long_name: str


#: Every scalar measured from a 1-DOF run: the one place its units and long name are written. Datasets
#: (studies), sweeps and maps (analysis.sweep), the notebooks' quantity labels and the claims table read
#: them from here.
METRICS: dict[str, MetricInfo] = {
    "solver_ok": MetricInfo("1", "solver finished without failure (1) or failed (0)"),
    "outcome": MetricInfo(
        "1", "run outcome (" + ", ".join(f"{i} {name}" for i, name in enumerate(OUTCOMES)) + ")"
    ),
    "stick_time": MetricInfo("s", "mean duration of complete stick intervals (steady window)"),
    "slip_time": MetricInfo("s", "mean duration of complete slip intervals (steady window)"),
    "first_stick_time": MetricInfo("s", "duration of the first stick interval"),
    "stick_count": MetricInfo("1", "number of complete stick intervals (steady window)"),
    "stick_fraction": MetricInfo("1", "fraction of steady-window samples in stick"),
    "slip_fraction": MetricInfo("1", "fraction of steady-window samples in slip"),
    "period": MetricInfo("s", "mean stick plus mean slip duration"),
    "amplitude_peak_to_peak": MetricInfo("mm", "peak-to-peak displacement (steady window)"),
    "amplitude_peak_to_zero": MetricInfo("mm", "largest |displacement| from zero (steady window)"),
    "max_displacement": MetricInfo("mm", "largest displacement (steady window)"),
    "min_displacement": MetricInfo("mm", "smallest displacement (steady window)"),
    "max_velocity": MetricInfo("mm s-1", "largest velocity (steady window)"),
    "min_velocity": MetricInfo("mm s-1", "smallest velocity (steady window)"),
    "max_speed": MetricInfo("mm s-1", "largest |velocity| (steady window)"),
    "max_speed_position": MetricInfo("mm", "displacement where |velocity| is largest"),
    "stick_velocity": MetricInfo("mm s-1", "mean velocity while sticking"),
    "stick_end_position": MetricInfo("mm", "displacement at which stick ends (steady window)"),
    "frequency_peaks": MetricInfo("Hz", "frequency from displacement peak spacing"),
    "frequency_spectrum": MetricInfo("Hz", "frequency of the spectral peak"),
    "peaks_in_count_window": MetricInfo("1", "displacement maxima in the first {count_window:g} s"),
    "periodic": MetricInfo("1", "last two cycles repeat to 1e-3 (1) or not (0)"),
    # beyond the limit cycle (``extra_metrics``): the decelerating belt and the friction curve
    "early_amplitude": MetricInfo(
        "mm", "peak-to-peak displacement, first half of the run (of the deceleration if the belt stops)"
    ),
    "late_amplitude": MetricInfo(
        "mm", "peak-to-peak displacement, second half of the run (of the deceleration if the belt stops)"
    ),
    "early_velocity_amplitude": MetricInfo("mm s-1", "peak-to-peak velocity, first half"),
    "late_velocity_amplitude": MetricInfo("mm s-1", "peak-to-peak velocity, second half"),
    "final_speed": MetricInfo("mm s-1", "|velocity| at the end of the run"),
    "friction_min_slip": MetricInfo("1", "smallest |F|/N while slipping (Fig. 17 plateau level)"),
    "relative_speed_max": MetricInfo("mm s-1", "largest |v_r| along the solution"),
}


def metric_attrs(name: str, **context) -> dict:
    """The CF attributes of a registered metric (``units``, ``long_name``)."""
    info = METRICS[name]
    return {"units": info.units, "long_name": info.long_name.format(**context)}


def cf_variable(dims, values, units: str, long_name: str, **attrs) -> tuple:
    """A dataset variable as xarray takes it, ``(dims, values, attrs)``, its units and long name first."""
    return dims, values, {"units": units, "long_name": long_name, **attrs}


def table_variables(dims, columns: dict[str, tuple[str, str]], values) -> dict[str, tuple]:
    """The ``cf_variable`` of every column of a table ``name -> (units, long_name)``, in its order, with
    ``values(name)`` as each one's data: a table of per-run or per-case quantities as dataset variables."""
    return {name: cf_variable(dims, values(name), units, text) for name, (units, text) in columns.items()}


#: The limit-cycle table's names (``limit_cycle_metrics``), in order; the rest is ``extra_metrics``'.
CYCLE_METRICS = tuple(METRICS)[: tuple(METRICS).index("periodic") + 1]


def _no_cycle_metrics(traj: Trajectory, outcome: str, count_window: float) -> dict[str, Metric]:
    """The table of a run with no limit cycle to measure: every metric NaN, except what the run computed
    before it diverged (its first stick, when that stick ended inside the run)."""
    values = dict.fromkeys(CYCLE_METRICS, float("nan"))
    values.update(solver_ok=0.0, outcome=float(outcome_code(outcome)))
    if outcome == "diverged" and traj.segments is not None and len(traj.segments):
        stick, _slip = segment_runs(traj.segments)
        if len(stick) and stick[0, 1] < traj.t[-1]:
            values["first_stick_time"] = float(stick[0, 1] - stick[0, 0])
    return {name: metric(name, value, count_window=count_window) for name, value in values.items()}


def metric(name: str, value: float, **context) -> Metric:
    return Metric(float(value), **metric_attrs(name, **context))


def phase_runs(t: np.ndarray, phase: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(start, end) times of stick runs and of slip runs from per-sample phases.

    A run's boundaries are put midway between the last sample of one phase and the first of the next.
    """
    t = np.asarray(t, dtype=float)
    sticking = np.asarray(phase) == STICK
    change = np.nonzero(sticking[1:] != sticking[:-1])[0]
    edges = np.concatenate(([t[0]], 0.5 * (t[change] + t[change + 1]), [t[-1]]))
    starts_sticking = bool(sticking[0])
    runs = np.column_stack((edges[:-1], edges[1:]))
    kinds = np.array([(i % 2 == 0) == starts_sticking for i in range(len(runs))])
    return runs[kinds], runs[~kinds]


def segment_runs(segments: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(start, end) of stick runs and slip runs from an exact switching record (t0, t1, phase).

    Consecutive slip segments (forward and backward) form one slip run; a zero-length stick (a grazing
    touch of the belt velocity) is kept as a stick run of length zero, so it still separates two slips.
    """
    stick, slip = [], []
    current = None
    for t0, t1, ph in segments:
        if ph == STICK:
            if current is not None:
                slip.append(current)
                current = None
            if stick and stick[-1][1] == t0:
                stick[-1] = (stick[-1][0], t1)
            else:
                stick.append((t0, t1))
        else:
            current = (t0, t1) if current is None else (current[0], t1)
    if current is not None:
        slip.append(current)
    return np.array(stick, dtype=float).reshape(-1, 2), np.array(slip, dtype=float).reshape(-1, 2)


def intervals(traj: Trajectory) -> tuple[np.ndarray, np.ndarray]:
    if traj.segments is not None and len(traj.segments):
        return segment_runs(traj.segments)
    return phase_runs(traj.t, traj.phase)


def displacement_peaks(t: np.ndarray, x: np.ndarray, rel_prominence: float = 0.01) -> np.ndarray:
    """Indices of displacement maxima whose prominence exceeds a fraction of the range."""
    span = np.nanmax(x) - np.nanmin(x)
    if not np.isfinite(span) or span <= 0:
        return np.array([], dtype=int)
    from scipy.signal import find_peaks  # here: scipy.signal costs ~1 s to import, most jobs never need it

    peaks, _ = find_peaks(x, prominence=rel_prominence * span)
    return peaks


def frequency_from_peaks(t: np.ndarray, x: np.ndarray) -> float:
    """1 / mean spacing of displacement maxima [Hz]; NaN with fewer than two maxima."""
    peaks = displacement_peaks(t, x)
    if len(peaks) < 2:
        return np.nan
    return (len(peaks) - 1) / (t[peaks[-1]] - t[peaks[0]])


def frequency_from_spectrum(t: np.ndarray, x: np.ndarray, pad: int = 16) -> float:
    """Frequency of the largest spectral peak of x - mean [Hz] (Hann window, zero padding, parabolic fit)."""
    import scipy.fft  # here: a plotting job that reads metrics need not import it

    dt = np.diff(t)
    if len(t) < 8 or not np.allclose(dt, dt[0], rtol=1e-6, atol=0):
        raise ValueError("frequency_from_spectrum needs uniformly sampled data")
    y = (x - np.mean(x)) * np.hanning(len(x))
    n = scipy.fft.next_fast_len(pad * len(y), real=True)  # pad*len can have a large prime factor: 20x slower
    power = np.abs(scipy.fft.rfft(y, n)) ** 2
    power[0] = 0.0
    k = int(np.argmax(power))
    if k == 0 or not np.any(power > 0):
        return np.nan
    shift = 0.0
    if 0 < k < len(power) - 1:
        a, b, c = np.log(power[k - 1 : k + 2] + 1e-300)
        denom = a - 2 * b + c
        shift = 0.5 * (a - c) / denom if denom != 0 else 0.0
    return (k + shift) / (n * dt[0])


def count_peaks(t: np.ndarray, x: np.ndarray, t_from: float, t_to: float) -> int:
    """Number of displacement maxima in [t_from, t_to] (the paper counts 'four peaks in 18 seconds')."""
    peaks = displacement_peaks(t, x)
    return int(np.sum((t[peaks] >= t_from) & (t[peaks] <= t_to)))


#: The window of the paper's peak count ("four peaks in 18 seconds", Section 3): the default of every study.
PAPER_COUNT_WINDOW = 18.0


def limit_cycle_metrics(
    traj: Trajectory, transient: float, count_window: float = PAPER_COUNT_WINDOW
) -> dict[str, Metric]:
    """The metric table of one run; the steady window is t >= ``transient``."""
    t, x, v = traj.t, traj.x, traj.v
    nan = float("nan")
    outcome = run_outcome(traj, transient)
    if outcome in ("diverged", "failed"):
        return _no_cycle_metrics(traj, outcome, count_window)
    window = t >= transient
    tw, xw, vw = t[window], x[window], v[window]
    stick, slip = intervals(traj)
    t_end = t[-1]
    stick_c = stick[(stick[:, 0] >= transient) & (stick[:, 1] < t_end) & (stick[:, 0] > t[0])]
    slip_c = slip[(slip[:, 0] >= transient) & (slip[:, 1] < t_end) & (slip[:, 0] > t[0])]
    stick_len = stick_c[:, 1] - stick_c[:, 0]
    slip_len = slip_c[:, 1] - slip_c[:, 0]
    # where each stick ends, the mass is released: interpolate x there
    release = np.interp(stick_c[:, 1], t, x) if len(stick_c) else np.array([])
    speed_at = int(np.argmax(np.abs(vw))) if len(vw) else 0
    peaks = displacement_peaks(tw, xw)
    peak_values = xw[peaks]
    periodic = nan
    if len(peaks) >= 3:
        spacing = np.diff(tw[peaks])
        periodic = float(
            np.abs(peak_values[-1] - peak_values[-2]) <= 1e-3 * max(np.ptp(xw), 1e-12)
            and np.abs(spacing[-1] - spacing[-2]) <= 1e-3 * spacing[-1] + 2 * (tw[1] - tw[0])
        )

    def mean(a):
        return float(np.mean(a)) if len(a) else nan

    # A window that has come to rest has no frequency: its "peaks" would be round-off or solver noise.
    at_rest = np.ptp(xw) <= REST_FRACTION * max(np.ptp(x), 1e-300)
    freq_peaks = nan if at_rest else frequency_from_peaks(tw, xw)
    freq_spectrum = nan if at_rest else frequency_from_spectrum(tw, xw)

    values = {
        "solver_ok": 1.0,
        "outcome": float(outcome_code(outcome)),
        "stick_time": mean(stick_len),
        "slip_time": mean(slip_len),
        "first_stick_time": float(stick[0, 1] - stick[0, 0]) if len(stick) else nan,
        "stick_count": float(len(stick_c)),
        "stick_fraction": float(np.mean(traj.phase[window] == STICK)) if window.any() else nan,
        "period": mean(stick_len) + mean(slip_len),
        "amplitude_peak_to_peak": float(np.ptp(xw)),
        "amplitude_peak_to_zero": float(np.max(np.abs(xw))),
        "max_displacement": float(np.max(xw)),
        "min_displacement": float(np.min(xw)),
        "max_velocity": float(np.max(vw)),
        "min_velocity": float(np.min(vw)),
        "max_speed": float(np.abs(vw[speed_at])),
        "max_speed_position": float(xw[speed_at]),
        "stick_velocity": float(np.mean(v[traj.phase == STICK])) if np.any(traj.phase == STICK) else nan,
        "stick_end_position": mean(release),
        "frequency_peaks": freq_peaks,
        "frequency_spectrum": freq_spectrum,
        "peaks_in_count_window": float(count_peaks(t, x, 0.0, count_window)),
        "periodic": periodic,
    }
    return {name: metric(name, value, count_window=count_window) for name, value in values.items()}


def extra_metrics(t, x, v, vb, phase, friction, normal_force: float) -> dict[str, float]:
    """The registered metrics beyond the limit cycle: early/late (velocity) amplitude of a decelerating belt
    (Fig. 15), the final speed (Fig. 16 settles), the smallest slip friction coefficient (Fig. 17) and the
    largest relative speed."""
    t, x, v, vb = (np.asarray(a, dtype=float) for a in (t, x, v, vb))
    # Halves of the run, or of the deceleration phase when the belt stops: comparing "before" with "after the
    # belt has stopped" would make any decay claim true by construction.
    stopped = vb <= 0.0
    t_ref = float(t[np.argmax(stopped)]) if stopped.any() else float(t[-1])
    half = t <= 0.5 * t_ref
    late = ~half & (t <= t_ref)
    _, mu_slip = friction_along_solution(v, vb, phase, friction, normal_force)
    with np.errstate(all="ignore"):
        return {
            "early_amplitude": float(np.ptp(x[half])),
            "late_amplitude": float(np.ptp(x[late])),
            "early_velocity_amplitude": float(np.ptp(v[half])),
            "late_velocity_amplitude": float(np.ptp(v[late])),
            "final_speed": float(abs(v[-1])),
            "friction_min_slip": float(np.min(mu_slip)) if mu_slip.size else np.nan,
            "relative_speed_max": float(np.max(np.abs(v - vb))),
        }
