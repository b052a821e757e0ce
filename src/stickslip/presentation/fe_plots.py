"""Figures of the beam-on-disc scenes (Sections 9-12): presentation only, reads datasets and draws.

A scene dataset holds per-bin min/max/mean over the whole run (``bin_time``) and full-resolution samples
only inside a few windows (``time``); the figures draw the whole run as an envelope band and the windows
sample by sample, so that a 12.9 kHz oscillation is never drawn from too few points.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

STATE_COLOURS = {0: ("separated", "#d62728"), 1: ("stick", "#2ca02c"), 2: ("slip", "#ffbf00")}
MODEL_STYLE = {"beam": dict(color="C0"), "continuum": dict(color="k")}
UM = 1e3  # mm -> micrometre (overview figures); the scene figures use the paper's mm and mm/s


def _sci(ax):
    """Scientific tick labels (the paper's displacements are 1e-4 mm)."""
    ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3), useMathText=True)


def _band(ax, ds, var, label, style, scale=1.0):
    t = ds.bin_time.values
    lo, hi = ds[f"{var}_min"].values * scale, ds[f"{var}_max"].values * scale
    ax.fill_between(t, lo, hi, alpha=0.35, lw=0, color=style["color"], label=f"{label} (min-max per bin)")
    ax.plot(t, ds[f"{var}_mean"].values * scale, lw=0.8, color=style["color"], label=f"{label} (bin mean)")


def _state_strip(ax, ds):
    """Per-bin stick / slip / separation fractions as a stacked strip."""
    t = ds.bin_time.values
    base = np.zeros_like(t)
    for code, name in ((1, "stick"), (2, "slip"), (0, "separation")):
        frac = np.nan_to_num(ds[f"{name}_fraction_per_bin"].values)
        ax.fill_between(t, base, base + frac, step="mid", color=STATE_COLOURS[code][1], lw=0, label=name)
        base = base + frac
    ax.set_ylim(0, 1)
    ax.set_ylabel("state\nfraction", fontsize=8)


def _shade_states(ax, t, state):
    """Shade contiguous runs of each contact state behind a full-resolution window."""
    if t.size < 2:
        return
    edges = np.flatnonzero(np.diff(state)) + 1
    starts = np.concatenate([[0], edges])
    ends = np.concatenate([edges, [t.size]])
    for a, b in zip(starts, ends):
        code = int(state[a])
        t1 = t[b] if b < t.size else t[-1]
        ax.axvspan(t[a], t1, color=STATE_COLOURS[code][1], alpha=0.18, lw=0)


def _window(ds, w):
    t0, t1 = ds.detail_windows.values[w]
    m = (ds.time.values >= t0) & (ds.time.values <= t1)
    return m


def _spectrum(t, y):
    y = y - y.mean()
    dt = float(np.median(np.diff(t)))
    spec = np.abs(np.fft.rfft(y * np.hanning(y.size))) * 2 / max(y.size, 1)
    return np.fft.rfftfreq(y.size, dt), spec


def _running_envelope(ax, ds, var, style):
    """Half peak-to-peak per window (the running envelope a growth claim is judged on), as a staircase
    around the window mean 0 (drawn +-)."""
    key = f"{var}_envelope"
    if key not in ds or "window_time" not in ds.coords:
        return
    t, env = ds.window_time.values, ds[key].values
    ax.step(t, env, where="mid", lw=1.2, ls="--", color=style["color"], alpha=0.9, label="running envelope")


def fe_scene_figure(beam, continuum=None, reported: dict | None = None, title: str = ""):
    """One paper scene, in the paper's units (mm, mm/s, N): whole-run envelopes of node 1's horizontal and
    vertical displacement and velocity (beam and continuum) with the running half peak-to-peak per window
    (what "increases" is judged on), the state strip, the spectrum and the contact forces of the last
    window with the zero line (separation), and the first and last windows sample by sample with
    stick/slip/separation shaded.

    ``reported``: optional {label: mm} of the paper's numbers, drawn on the horizontal displacement."""
    models = {"beam": beam} | ({"continuum": continuum} if continuum is not None else {})
    fig = plt.figure(figsize=(13, 15))
    gs = fig.add_gridspec(7, 2, height_ratios=[3, 3, 3, 3, 0.8, 3, 3], hspace=0.6, wspace=0.22)
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
            _band(ax, beam, f"midspan_{var}", "beam, mid-span node (off the contact)", dict(color="C2"))
        for name, ds in models.items():
            _band(ax, ds, var, name, MODEL_STYLE[name])
        _running_envelope(ax, beam, var, MODEL_STYLE["beam"])
        ax.set_ylabel(ylabel)
        _sci(ax)
        ax.grid(alpha=0.25)
    for key, val in (reported or {}).items():
        ax_x.axhline(val, color="C3", ls="--", lw=1)
        box = dict(fc="white", ec="none", alpha=0.8, pad=0.5)
        where = ("axes fraction", "data")
        ax_x.annotate(f"paper: {key} {val:g} mm", (0.995, val), xycoords=where, ha="right", va="bottom",
                      color="C3", fontsize=8, bbox=box)  # fmt: skip
    ax_x.legend(fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=5, frameon=False)
    if "midspan_vertical_displacement_min" in beam:
        ax_y.legend(fontsize=7, loc="lower right", ncol=3)
    _state_strip(ax_s, beam)
    ax_s.legend(fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=3, frameon=False)
    ax_s.set_xlabel("time [s] (beam state fractions per bin)")
    # spectra of the last full-resolution window (dominant frequency panel)
    ax_f = fig.add_subplot(gs[5, 0])
    for name, ds in models.items():
        m = _window(ds, -1)
        if m.sum() > 8:
            f, a = _spectrum(ds.time.values[m], ds.horizontal_displacement.values[m])
            ax_f.loglog(f[1:], a[1:], lw=0.8, label=name, **MODEL_STYLE[name])
        fd = float(ds["dominant_frequency"])
        ax_f.axvline(fd, ls=":", lw=1, color=MODEL_STYLE[name]["color"])
    ax_f.set_xlabel("frequency [Hz] (horizontal u, last window; dotted: dominant over the 2nd half)")
    ax_f.set_ylabel("amplitude [mm]")
    ax_f.legend(fontsize=7)
    ax_n = fig.add_subplot(gs[5, 1])
    for name, ds in models.items():
        m = _window(ds, -1)
        ax_n.plot(
            ds.time.values[m], ds.normal_force.values[m], lw=0.7, label=f"{name} normal", **MODEL_STYLE[name]
        )
    m = _window(beam, -1)
    ax_n.plot(beam.time.values[m], beam.friction_force.values[m], lw=0.7, color="C1", label="beam friction")
    ax_n.axhline(0.0, color="C3", lw=0.8, ls="-", label="zero (separation)")
    ax_n.set_ylabel("contact force [N]")
    _sci(ax_n)
    ax_n.set_xlabel("time [s] (last window)")
    ax_n.legend(fontsize=7)
    f_dom = float(beam["dominant_frequency"])
    for col, w in enumerate((0, -1)):
        ax = fig.add_subplot(gs[6, col])
        t0, t1 = beam.detail_windows.values[w]
        if col == 1 and f_dom > 0 and 10 / f_dom < t1 - t0:  # the last ten periods of the dominant mode
            t0 = t1 - 10 / f_dom
        mb = _window(beam, w) & (beam.time.values >= t0)
        _shade_states(ax, beam.time.values[mb], beam.contact_state.values[mb])
        for name, ds in models.items():
            m = _window(ds, w) & (ds.time.values >= t0)
            ax.plot(
                ds.time.values[m],
                ds.horizontal_displacement.values[m],
                lw=0.8,
                label=name,
                **MODEL_STYLE[name],
            )
        what = "first window" if col == 0 else f"last {t1 - t0:.3g} s"
        ax.set_xlabel(f"time [s]: {what}, every sample (shading: beam state)")
        ax.set_ylabel("horizontal u [mm]")
        _sci(ax)
        ax.legend(fontsize=7, loc="upper right")
    fig.suptitle(title or beam.attrs.get("title", ""), fontsize=11)
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
        if yscale == "symlog":
            ax.set_yscale("symlog", linthresh=1e-3)
        else:
            ax.set_yscale(yscale)
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
    a2.bar(x - 0.27, ds.crosscheck_eigen_growth_rate.values, 0.27, label="eigenvalue (sliding N)")
    a2.bar(x, ds.crosscheck_transient_growth_rate.values, 0.27, label="explicit transient")
    a2.bar(
        x + 0.27,
        ds.crosscheck_eigen_growth_rate_static_normal.values,
        0.27,
        label="eigenvalue (static N, old)",
    )
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
