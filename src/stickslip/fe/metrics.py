"""Scalar metrics of a beam-on-disc trajectory (contact point = the paper's "node 1").

Displacements are measured from the gravity equilibrium in contact (the state the disc starts from), so
they show the friction-induced motion the paper's Figs. 21-36 plot.
"""

from __future__ import annotations

import numpy as np

from .explicit import ExplicitResult


def dominant_frequency(t: np.ndarray, x: np.ndarray, f_min: float = 0.0) -> float:
    """Frequency [Hz] of the largest spectral peak of the detrended signal (Hann window), refined by
    parabolic interpolation of the log-magnitude; 0 if the signal is constant."""
    if t.size < 8:
        return 0.0
    y = x - np.mean(x)
    if not np.any(np.abs(y) > 0):
        return 0.0
    dt = float(np.median(np.diff(t)))
    spec = np.abs(np.fft.rfft(y * np.hanning(y.size)))
    freqs = np.fft.rfftfreq(y.size, dt)
    spec[freqs <= f_min] = 0.0
    spec[0] = 0.0
    k = int(np.argmax(spec))
    if 0 < k < spec.size - 1 and spec[k - 1] > 0 and spec[k + 1] > 0:
        a, b, c = np.log(spec[k - 1 : k + 2])
        den = a - 2 * b + c
        delta = 0.5 * (a - c) / den if den != 0 else 0.0
        return float((k + delta) * (freqs[1] - freqs[0]))
    return float(freqs[k])


def window_envelope(t: np.ndarray, x: np.ndarray, n_windows: int = 10):
    """Half peak-to-peak of x in ``n_windows`` equal time windows -> (window centre times, envelope)."""
    edges = np.linspace(t[0], t[-1], n_windows + 1)
    idx = np.clip(np.searchsorted(t, edges), 0, t.size)
    centres, env = [], []
    for a, b in zip(idx[:-1], idx[1:]):
        seg = x[a : max(b, a + 1)]
        centres.append(0.5 * (t[a] + t[min(max(b, a + 1), t.size) - 1]))
        env.append(0.5 * (seg.max() - seg.min()))
    return np.asarray(centres), np.asarray(env)


def trend_sign(y: np.ndarray, rel: float = 0.05) -> int:
    """+1/-1 if the least-squares slope changes y by more than ``rel`` of its mean over the range, else 0."""
    if y.size < 2 or not np.any(y):
        return 0
    s = np.polyfit(np.arange(y.size), y, 1)[0] * (y.size - 1)
    scale = np.mean(np.abs(y))
    return 0 if abs(s) <= rel * scale else int(np.sign(s))


def _second_half_fractions(r: ExplicitResult, half: np.ndarray) -> dict:
    """Stick/slip/separation fractions after half the run: from the increment counts when the integrator
    kept them (``extra['second_half_counts']``), else from the output samples."""
    if "second_half_counts" in r.extra:
        f = r.fractions("second_half")
    else:
        st = r.state[half]
        n = max(st.size, 1)
        f = {"separation": float((st == 0).sum() / n), "stick": float((st == 1).sum() / n)}
        f["slip"] = float((st == 2).sum() / n)
    return {"stick_fraction": f["stick"], "slip_fraction": f["slip"], "separation_fraction": f["separation"]}


def trajectory_metrics(r: ExplicitResult, natural_frequencies: np.ndarray | None = None) -> dict:
    """Scalar metrics; units: mm, mm s-1, Hz, N, s, fractions [-]."""
    x = r.x - r.x[0]
    y = r.y - r.y[0]
    half = r.t >= 0.5 * r.t[-1]
    m = {
        "max_horizontal_displacement": float(x.max()),
        "min_horizontal_displacement": float(x.min()),
        "max_abs_horizontal_displacement": float(np.abs(x).max()),
        "mean_horizontal_displacement": float(x[half].mean()),
        "abs_mean_horizontal_displacement": float(abs(x[half].mean())),
        "horizontal_amplitude": float(0.5 * (x[half].max() - x[half].min())),
        "max_vertical_displacement": float(np.abs(y).max()),
        "vertical_amplitude": float(0.5 * (y[half].max() - y[half].min())),
        "max_abs_horizontal_velocity": float(np.abs(r.vx).max()),
        "max_abs_vertical_velocity": float(np.abs(r.vy).max()),
        "dominant_frequency": dominant_frequency(r.t[half], x[half]),
        "vertical_dominant_frequency": dominant_frequency(r.t[half], y[half]),
        **_second_half_fractions(r, half),
        "stick_fraction_whole_run": r.fractions()["stick"],
        "separation_fraction_whole_run": r.fractions()["separation"],
        "static_normal_force": r.static_normal_force,
        "max_normal_force_ratio": float(r.normal_force.max() / r.static_normal_force)
        if r.static_normal_force > 0
        else np.nan,
        "stable_time_step": r.dt_crit,
        "time_step": r.dt,
        "increment_count": int(r.n_steps),
        "increment_count_0p65s": int(np.ceil(0.65 / r.dt)),
        "cpu_time": r.cpu_time,
    }
    stick_t = r.t[r.state == 1]
    m["stick_end_time"] = float(stick_t.max()) if stick_t.size else 0.0
    first_slip = r.t[r.state != 1]
    m["first_stick_duration"] = float(first_slip.min()) if first_slip.size else float(r.t[-1])
    xs = x[half] - x[half].mean()
    ys = y[half] - y[half].mean()
    den = np.sqrt((xs**2).sum() * (ys**2).sum())
    m["horizontal_vertical_correlation"] = float((xs * ys).sum() / den) if den > 0 else 0.0
    m["separation_burst_time"] = separation_burst_time(r.t, r.state)
    _, envx = window_envelope(r.t, x)
    m["horizontal_amplitude_growth_ratio"] = float(envx[-1] / envx[1]) if envx[1] > 0 else np.nan
    if natural_frequencies is not None and len(natural_frequencies):
        nf = np.asarray(natural_frequencies)
        for key, src in (("dominant_frequency", "horizontal"), ("vertical_dominant_frequency", "vertical")):
            f = m[key]
            m[f"{src}_nearest_mode_ratio"] = float(f / nf[np.argmin(np.abs(nf - f))]) if f > 0 else np.nan
    return m


def mode_amplitude(t: np.ndarray, x: np.ndarray, frequency: float, window: float = 0.05):
    """Amplitude of x's component at ``frequency`` [Hz] per time window of ``window`` seconds, by complex
    demodulation with a Hann weight w (2 |sum w (x - xbar) e^{-i 2 pi f t}| / sum w, xbar the weighted
    mean) -> (window centre times, amplitudes). A window holds many periods of the mode (18 of the 366 Hz
    bending mode in 50 ms) and the Hann weight keeps a window's fractional period and the other modes (the
    12.9 kHz axial chatter, an offset) from leaking into it."""
    # a run's last sample may fall short of its end by up to an output interval: the last window counts
    # when it is full to a thousandth
    n = int(np.floor((t[-1] - t[0]) / window + 1e-3))
    centres, amps = [], []
    for k in range(n):
        m = (t >= t[0] + k * window) & (t < t[0] + (k + 1) * window)
        if m.sum() < 8:
            continue
        tt = t[m]
        w = np.hanning(tt.size)
        xx = x[m] - np.sum(w * x[m]) / np.sum(w)
        centres.append(float(tt.mean()))
        amps.append(float(2.0 * abs(np.sum(w * xx * np.exp(-2j * np.pi * frequency * tt))) / np.sum(w)))
    return np.asarray(centres), np.asarray(amps)


def leading_growth_rate(t: np.ndarray, amplitude: np.ndarray, drop: float = 0.05) -> tuple[float, float]:
    """(growth rate [s-1], end time [s]) of an amplitude series: the least-squares slope of log(amplitude)
    over its leading segment. A series that grows by more than ``drop`` and then falls more than ``drop``
    below its running maximum (a burst or collapse ends the linear growth) is fitted up to the peak before
    that fall; any other series (decaying, flat) over every sample. NaN with fewer than 3 samples in the
    segment or a zero amplitude in it."""
    if amplitude.size < 3:
        return float("nan"), float("nan")
    run_max = np.maximum.accumulate(amplitude)
    falls = np.flatnonzero(amplitude < (1.0 - drop) * run_max)
    grew_first = falls.size and run_max[falls[0]] > (1.0 + drop) * amplitude[0]
    end = int(np.argmax(amplitude[: falls[0]])) + 1 if grew_first else amplitude.size
    seg_t, seg_a = t[:end], amplitude[:end]
    if seg_t.size < 3 or np.any(seg_a <= 0):
        return float("nan"), float("nan")
    return float(np.polyfit(seg_t, np.log(seg_a), 1)[0]), float(seg_t[-1])


#: window [s] over which separation_burst_time counts separated samples (1.8 periods of the 366 Hz bending
#: mode, 65 of the 12.9 kHz axial chatter whose increments separate)
BURST_WINDOW = 0.005
#: a burst: a window whose separated fraction reaches this share of the run's largest window fraction
BURST_LEVEL = 0.5


def separation_burst_time(
    t: np.ndarray, state: np.ndarray, window: float = BURST_WINDOW, level: float = BURST_LEVEL
) -> float:
    """Start [s] of the first separation burst: the run cut into windows of ``window`` seconds from t[0],
    the first window whose fraction of separated samples (contact state 0) reaches ``level`` times the
    largest window fraction of the run. Scale-free: the burst that ends the linear growth of the first mode
    (separated ~37 % of a window, against a few per cent before it) is found whatever the run's chatter
    level. NaN when the contact never separates."""
    if t.size == 0:
        return float("nan")
    n = max(int(np.ceil((t[-1] - t[0]) / window - 1e-9)), 1)
    k = np.minimum(((t - t[0]) / window).astype(np.int64), n - 1)
    counts = np.bincount(k, minlength=n).astype(float)
    sep = np.bincount(k, weights=(np.asarray(state) == 0).astype(float), minlength=n)
    frac = np.divide(sep, counts, out=np.zeros(n), where=counts > 0)
    if not np.any(frac > 0):
        return float("nan")
    first = int(np.flatnonzero(frac >= level * frac.max())[0])
    return float(t[0] + first * window)
