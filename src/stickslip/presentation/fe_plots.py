"""Figures of the beam-on-disc scenes (Sections 9-12): presentation only, reads datasets and draws.

A scene dataset holds per-bin min/max/mean over the whole run (``bin_time``) and full-resolution samples
only inside a few windows (``time``); the figures draw the whole run as an envelope band and the windows
sample by sample, so that a 12.9 kHz oscillation is never drawn from too few points.
"""

from __future__ import annotations

import warnings

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch
from matplotlib.ticker import FuncFormatter

STATE_COLOURS = {0: ("separated", "#d62728"), 1: ("stick", "#2ca02c"), 2: ("slip", "#ffbf00")}
MODEL_STYLE = {"beam": dict(color="C0"), "continuum": dict(color="k")}
UM = 1e3  # mm -> micrometre (overview figures); the scene figures use the paper's mm and mm/s
#: the white box behind a note on the data (a paper's number, a withheld value)
NOTE_BOX = dict(fc="white", ec="none", alpha=0.8, pad=0.3)
PAPER_COLOUR = "C3"  #: what the paper reports


def sci_ticks(ax):
    """Scientific tick labels (the paper's displacements are 1e-4 mm)."""
    ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3), useMathText=True)


#: pixel columns a whole-run band is reduced to (a 13-inch panel at dpi 100 has < 1000): no moire
N_COLUMNS = 800


def band_columns(ds, var, n=N_COLUMNS, t_max=None):
    """Per-bin min/max of ``var`` (bins up to ``t_max``) reduced to at most ``n`` columns: (t, min, max).

    Where a period of the dominant frequency spans fewer than 8 columns the waveform cannot be drawn, and
    columns shorter than a period would alias it into a false beat: the columns are then widened to two
    periods, so the band is the envelope."""
    t = ds.bin_time.values
    keep = slice(None) if t_max is None else t <= t_max
    t, lo, hi = t[keep], ds[f"{var}_min"].values[keep], ds[f"{var}_max"].values[keep]
    k = max(1, int(np.ceil(t.size / n)))
    f = float(ds["dominant_frequency"]) if "dominant_frequency" in ds else float("nan")
    dt = float(np.median(np.diff(t))) if t.size > 1 else 0.0
    if np.isfinite(f) and f > 0 and dt > 0 and 1.0 / f < 8 * k * dt:
        k = max(k, int(np.ceil(2.0 / (f * dt))))
    if k == 1 or t.size == 0:
        return t, lo, hi
    return grouped(t, k, np.nanmean), grouped(lo, k, np.nanmin), grouped(hi, k, np.nanmax)


def grouped(x, k, reduce):
    """``reduce`` over consecutive groups of ``k`` values (the last group may be shorter)."""
    pad = -x.size % k
    x = np.concatenate([x.astype(float), np.full(pad, np.nan)]) if pad else x
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # an all-NaN group stays NaN (a gap, not an error)
        return reduce(x.reshape(-1, k), axis=1)


def power_of_ten(axes) -> int:
    """The power of ten of the largest |y limit| over ``axes``: the one scale of a quantity drawn in several
    panels (0 within 1e-2..1e2, where plain numbers read best)."""
    top = max((abs(v) for ax in axes for v in ax.get_ylim()), default=0.0)
    e = int(np.floor(np.log10(top))) if top > 0 else 0
    return 0 if -2 <= e <= 2 else e


def scaled_ylabel(ax, text: str, unit: str, fontsize=8, exponent: int | None = None):
    """Y label with the unit and the power of ten of the tick labels in it ("[10^-4 mm]"), instead of an
    offset text that a legend above the panel would cover. ``exponent``: the power of ten to use (the
    same for every panel of one quantity: ``power_of_ten`` over them); default this panel's own."""
    e = power_of_ten([ax]) if exponent is None else int(exponent)
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v / 10.0**e:g}"))
    ax.set_ylabel(f"{text} [{unit}]" if e == 0 else f"{text} [$10^{{{e}}}$ {unit}]", fontsize=fontsize)


def axes_note(ax, x, y, text, **style):
    """A note at the axes fraction (``x``, ``y``), 8 pt unless ``style`` says otherwise."""
    return ax.text(x, y, text, transform=ax.transAxes, **{"fontsize": 8, **style})


def paper_line(ax, y, text, ls="--", lw=1.2, x=0.99, bbox=NOTE_BOX):
    """What the paper states about a level: a horizontal line in the paper's colour, labelled above it at
    the right edge (``x`` 0.99) or the left one."""
    ax.axhline(y, color=PAPER_COLOUR, ls=ls, lw=lw)
    where = dict(xycoords=("axes fraction", "data"), ha="right" if x > 0.5 else "left", va="bottom")
    ax.annotate(text, (x, y), **where, fontsize=8, color=PAPER_COLOUR, bbox=bbox)


def _band(ax, ds, var, label, style, t_max=None):
    t, lo, hi = band_columns(ds, var, t_max=t_max)
    ax.fill_between(t, lo, hi, alpha=0.35, lw=0, color=style["color"], label=f"{label} (min-max)")


def _state_strip(ax, ds, t_max=None):
    """Per-bin stick / slip / separation fractions as a stacked strip."""
    t = ds.bin_time.values
    keep = slice(None) if t_max is None else t <= t_max
    t = t[keep]
    base = np.zeros_like(t)
    for code, name in ((1, "stick"), (2, "slip"), (0, "separation")):
        frac = np.nan_to_num(ds[f"{name}_fraction_per_bin"].values[keep])
        ax.fill_between(t, base, base + frac, step="mid", color=STATE_COLOURS[code][1], lw=0, label=name)
        base = base + frac
    ax.set_ylim(0, 1)
    ax.set_ylabel("state\nfraction", fontsize=8)


def shade_states(ax, t, state, alpha=0.18):
    """Contact state behind a full-resolution window, as one image strip over the axes' height (one artist
    however often the state switches: the 12.9 kHz chatter switches hundreds of times in 5 ms). Call after
    the data are drawn: the axes' limits are kept."""
    if t.size < 2:
        return
    lims = ax.get_xlim(), ax.get_ylim()
    cmap = ListedColormap([STATE_COLOURS[k][1] for k in sorted(STATE_COLOURS)])
    ax.imshow(state[None, :].astype(float), extent=(t[0], t[-1], 0, 1), transform=ax.get_xaxis_transform(),
              aspect="auto", cmap=cmap, vmin=-0.5, vmax=len(STATE_COLOURS) - 0.5, alpha=alpha,
              interpolation="nearest", zorder=0)  # fmt: skip
    ax.set_xlim(*lims[0])
    ax.set_ylim(*lims[1])


def state_legend_handles(alpha=0.18):
    """Legend entries of the three contact states (drawn whether or not a window shows each)."""
    return [Patch(color=c, alpha=alpha, label=name) for name, c in STATE_COLOURS.values()]


def detail_window(ds, w):
    """(start, end, mask of the full-resolution samples) of the dataset's detail window ``w``."""
    t0, t1 = ds.detail_windows.values[w]
    return t0, t1, (ds.time.values >= t0) & (ds.time.values <= t1)


def _between(ds, t0, t1):
    """Mask of the full-resolution samples in [t0, t1] (to round-off)."""
    return (ds.time.values >= t0 - 1e-9) & (ds.time.values <= t1 + 1e-9)


def _samples_or_bins(ax, ds, model, var, t0, t1, t_max, lw, label, binned_label):
    """A model's full-resolution samples of ``var`` in [t0, t1] where it kept them, else its per-bin min-max
    band from ``t0`` on."""
    m = _between(ds, t0, t1)
    if m.sum() > 1:
        ax.plot(ds.time.values[m], ds[var].values[m], lw=lw, label=label, **MODEL_STYLE[model])
    elif f"{var}_min" in ds:
        t, lo, hi = band_columns(ds, var, t_max=t_max)
        keep = t >= t0
        style = MODEL_STYLE[model]
        ax.fill_between(
            t[keep], lo[keep], hi[keep], alpha=0.35, lw=0, step="mid", label=binned_label, **style
        )


def _spectrum(t, y):
    y = y - y.mean()
    dt = float(np.median(np.diff(t)))
    spec = np.abs(np.fft.rfft(y * np.hanning(y.size))) * 2 / max(y.size, 1)
    return np.fft.rfftfreq(y.size, dt), spec


def envelope_windows(ds, var):
    """(window times, ``<var>_envelope``, window width) of the running envelope a growth claim is judged on
    (half peak-to-peak per window); None when the dataset has none."""
    key = f"{var}_envelope"
    if key not in ds or "window_time" not in ds.coords or ds.window_time.size == 0:
        return None
    t = ds.window_time.values
    return t, ds[key], float(np.median(np.diff(t))) if t.size > 1 else 2 * float(t[0])


def _running_envelope(ax, ds, var, style, t_max=None):
    """The running envelope (``envelope_windows``) as a staircase."""
    if (found := envelope_windows(ds, var)) is None:
        return
    t, env, w = found
    env = env.values
    keep = t - w / 2 < (np.inf if t_max is None else t_max - 1e-12)
    edges = np.concatenate([t[keep] - w / 2, [t[keep][-1] + w / 2]])
    ax.stairs(
        env[keep],
        edges,
        baseline=None,
        lw=1.2,
        ls="--",
        color=style["color"],
        alpha=0.9,
        label="running half peak-to-peak",
    )


def fe_scene_figure(beam, continuum=None, reported: dict | None = None, title: str = ""):
    """One paper scene, beam against the continuum strip, in the paper's units (mm, mm/s, N), over the
    window both models ran (the continuum's, the model-comparison window; the beam alone when no continuum
    is given): node 1's horizontal and vertical displacement and velocity as min-max bands (the beam's
    running half peak-to-peak per window dashed, the mid-span node where the vertical motion lives), the
    beam's state strip, the spectra of the first window (both models sample by sample at the same time),
    the contact forces over the last 5 ms of the window with the zero line (separation), and the first and
    last 5 ms with the contact state shaded. The beam's samples are kept only in its own detail windows, so
    where they are missing the beam is drawn as its per-bin band.

    ``reported``: optional {label: mm} of the paper's numbers, drawn on the horizontal displacement."""
    models = {"beam": beam} | ({"continuum": continuum} if continuum is not None else {})
    t_run = float(beam.time.values[-1])
    t_cmp = float(continuum.time.values[-1]) if continuum is not None else t_run
    t_max = t_cmp * (1 + 1e-9) + 0.5 * float(np.median(np.diff(beam.bin_time.values)))
    fig = plt.figure(figsize=(13, 16.5))
    gs = fig.add_gridspec(
        7, 2, height_ratios=[3, 3, 3, 3, 0.8, 3, 3], hspace=0.75, wspace=0.22, top=0.91, bottom=0.04
    )
    ax_x = fig.add_subplot(gs[0, :])
    ax_y = fig.add_subplot(gs[1, :], sharex=ax_x)
    ax_vx = fig.add_subplot(gs[2, :], sharex=ax_x)
    ax_vy = fig.add_subplot(gs[3, :], sharex=ax_x)
    ax_s = fig.add_subplot(gs[4, :], sharex=ax_x)
    panels = (
        (ax_x, "horizontal_displacement", "horizontal u\nnode 1 [mm]"),
        (ax_y, "vertical_displacement", "vertical v\nnode 1, mid-span [mm]"),
        (ax_vx, "horizontal_velocity", "horizontal du/dt\nnode 1 [mm/s]"),
        (ax_vy, "vertical_velocity", "vertical dv/dt\nnode 1, mid-span [mm/s]"),
    )
    for ax, var, ylabel in panels:
        off = f"midspan_{var}_min"
        if var.startswith("vertical") and off in beam and float(np.abs(beam[off]).max()) > 0:
            _band(
                ax, beam, f"midspan_{var}", "beam, mid-span node (off the contact)", dict(color="C2"), t_max
            )
        for name, ds in models.items():
            _band(ax, ds, var, name, MODEL_STYLE[name], t_max)
        _running_envelope(ax, beam, var, MODEL_STYLE["beam"], t_max)
        ax.set_ylabel(ylabel)
        sci_ticks(ax)
        ax.grid(alpha=0.25)
    ax_x.set_xlim(0.0, t_max)
    for key, val in (reported or {}).items():
        paper_line(ax_x, val, f"paper: {key} {val:g} mm", lw=1, x=0.995, bbox={**NOTE_BOX, "pad": 0.5})
    # one legend for the four whole-run panels, above them (a legend inside would cover a band)
    handles = {}
    for ax in (ax_x, ax_y):
        for h, lab in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(lab, h)
    fig.legend(
        handles.values(),
        handles.keys(),
        fontsize=8,
        loc="lower center",
        ncol=3,
        frameon=False,
        bbox_to_anchor=(0.5, ax_x.get_position().y1 + 0.004),
    )
    _state_strip(ax_s, beam, t_max)
    ax_s.legend(fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3, frameon=False)
    ax_s.set_xlabel("time [s] (beam state fractions per bin)")
    # spectra of the first window: both models sample by sample over the same 5 ms
    ax_f = fig.add_subplot(gs[5, 0])
    for name, ds in models.items():
        m = detail_window(ds, 0)[2]
        if m.sum() > 8:
            f, a = _spectrum(ds.time.values[m], ds.horizontal_displacement.values[m])
            ax_f.loglog(f[1:], a[1:], lw=0.8, label=name, **MODEL_STYLE[name])
        ax_f.axvline(float(ds["dominant_frequency"]), ls=":", lw=1, color=MODEL_STYLE[name]["color"])
    ax_f.set_xlabel("frequency [Hz] (horizontal u, first window; dotted: dominant over the 2nd half)")
    ax_f.set_ylabel("amplitude [mm]")
    ax_f.legend(fontsize=7)
    # the last 5 ms of the comparison window: full-resolution samples where a model kept them, else its bins
    w_end = (t_cmp - 0.005, t_cmp)
    ax_n = fig.add_subplot(gs[5, 1])
    for name, ds in models.items():
        binned = f"{name} normal (min-max per bin)"
        _samples_or_bins(ax_n, ds, name, "normal_force", *w_end, t_max, 0.7, f"{name} normal", binned)
    if (m := _between(beam, *w_end)).sum() > 1:
        ax_n.plot(
            beam.time.values[m], beam.friction_force.values[m], lw=0.7, color="C1", label="beam friction"
        )
    ax_n.axhline(0.0, color="C3", lw=0.8, ls="-", label="zero (separation)")
    ax_n.set_xlim(*w_end)
    scaled_ylabel(ax_n, "contact force", "N", fontsize=10)
    ax_n.set_xlabel(f"time [s] (last 5 ms of the {t_cmp:.3g} s window)")
    ax_n.legend(fontsize=7, loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=3, frameon=False)
    ref = continuum if continuum is not None else beam
    windows = []
    for col, (t0, t1) in enumerate(((0.0, 0.005), w_end)):
        ax = fig.add_subplot(gs[6, col])
        windows.append(ax)
        for name, ds in models.items():
            binned = f"{name} (min-max per bin: no samples kept here)"
            _samples_or_bins(ax, ds, name, "horizontal_displacement", t0, t1, t_max, 0.8, name, binned)
        ax.set_xlim(t0, t1)
        m = _between(ref, t0, t1)
        shade_states(ax, ref.time.values[m], ref.contact_state.values[m])
        shade = "continuum" if continuum is not None else "beam"
        ax.set_xlabel(f"time [s]: {t0:.4g}-{t1:.4g} s, every sample (shading: {shade} state)")
        ax.legend(fontsize=7, loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=2, frameon=False)
    for ax in windows:  # one unit for the two windows of the same quantity
        scaled_ylabel(ax, "horizontal u", "mm", fontsize=10, exponent=power_of_ten(windows))
    shown = (
        f"the first {t_cmp:.3g} s, the model-comparison window (the beam ran {t_run:.3g} s)"
        if continuum is not None
        else f"the beam's whole run, {t_run:.3g} s (no continuum)"
    )
    fig.suptitle(f"{title or beam.attrs.get('title', '')}\nshown: {shown}", fontsize=11)
    return fig


def fe_readings_figure(datasets: dict, scenes: list, readings: list, reported: dict | None = None):
    """Horizontal amplitude, mean and dominant frequency of node 1 per scene and FE reading."""
    qs = (
        ("horizontal_amplitude", "half peak-to-peak u [µm]", UM, "log"),
        ("mean_horizontal_displacement", "mean u [µm]", UM, "symlog"),
        ("max_horizontal_displacement", "max u [µm]", UM, "symlog"),
        ("dominant_frequency", "dominant frequency [Hz]", 1.0, "log"),
        ("stick_fraction", "stick fraction", 1.0, "linear"),
    )
    fig, axes = plt.subplots(len(qs), 1, figsize=(12, 13), sharex=True)
    x = np.arange(len(scenes))
    w = 0.8 / max(len(readings), 1)
    for ax, (q, label, scale, yscale) in zip(axes, qs):
        for k, r in enumerate(readings):
            vals = [float(datasets[(r, s)][q]) * scale for s in scenes]
            ax.bar(x + (k - (len(readings) - 1) / 2) * w, vals, w, label=r)
        if reported and q in reported:
            ax.axhline(reported[q] * scale, color="C3", ls="--", lw=1.2, label="paper")
        ax.set_ylabel(label, fontsize=8)
        ax.set_yscale(yscale, **({"linthresh": 1e-3} if yscale == "symlog" else {}))
        ax.grid(axis="y", alpha=0.3)
    axes[0].legend(fontsize=7, ncol=3)
    axes[-1].set_xticks(x, [s.replace("_", "\n", 1) for s in scenes], fontsize=7)
    fig.suptitle("Node 1 per scene and FE reading (beam model)", fontsize=11)
    fig.tight_layout()
    return fig


def fe_convergence_figure(ds):
    qs = ("horizontal_amplitude", "mean_horizontal_displacement", "dominant_frequency", "stick_fraction")
    fig, axes = plt.subplots(1, len(qs), figsize=(15, 3.8))
    for ax, q in zip(axes, qs):
        for j, sf in enumerate(ds.safety_factor.values):
            ax.plot(ds.n_elements.values, ds[q].values[:, j], "o-", label=f"dt = {sf:g} dt_crit")
        ax.set_xscale("log")
        ax.set_xlabel("beam elements")
        dev = ds[f"{q}_max_deviation"]
        kind = "abs" if "absolute" in dev.attrs.get("long_name", "") else "rel"
        ax.set_title(f"{q.replace('_', ' ')}\nlargest {kind}. deviation {float(dev):.3g}", fontsize=9)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("Convergence in element count and time step (base scene)", fontsize=11)
    fig.tight_layout()
    return fig


def fe_stability_figure(ds):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(13, 4.5))
    g = ds.max_growth_rate.values
    im = a1.pcolormesh(ds.friction_slope.values, ds.contact_angle.values, g, shading="nearest", cmap="RdBu_r",
                       vmin=-np.abs(g).max(), vmax=np.abs(g).max())  # fmt: skip
    fig.colorbar(im, ax=a1, label="largest growth rate [s-1]")
    a1.set_xlabel("d mu / d v_r [s/mm]")
    a1.set_ylabel("contact angle [deg]")
    a1.set_title("linearised steady sliding (sliding normal force)", fontsize=9)
    lab = [f"{a:+.0f}°, {s:.3g}" for a, s in zip(ds.crosscheck_angle.values, ds.crosscheck_slope.values)]
    x = np.arange(len(lab))
    for dx, rate, label in (
        (-0.27, "eigen_growth_rate", "eigenvalue (sliding N)"),
        (0.0, "transient_growth_rate", "explicit transient"),
        (0.27, "eigen_growth_rate_static_normal", "eigenvalue (static N, old)"),
    ):
        a2.bar(x + dx, ds[f"crosscheck_{rate}"].values, 0.27, label=label)
    for i, (f, r) in enumerate(
        zip(ds.crosscheck_transient_frequency.values, ds.crosscheck_relative_difference.values)
    ):
        a2.annotate(f"{f / 1e3:.2f} kHz\n{100 * r:.1f} %", (i, ds.crosscheck_transient_growth_rate.values[i]),
                    ha="center", va="bottom", fontsize=7)  # fmt: skip
    a2.set_xticks(x, lab, fontsize=7, rotation=20)
    a2.set_ylabel("growth rate [s-1]")
    a2.set_title("cross-checks (labels: frequency that grows in the transient, |difference|)", fontsize=9)
    a2.legend(fontsize=7)
    fig.tight_layout()
    return fig
