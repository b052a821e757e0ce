"""A beam-on-disc run packed as a dataset: full-resolution samples inside windows, per-bin statistics over
the whole run, envelopes, the first mode's amplitude, the scalar metrics, and the static deflection and
contact-held mode shapes along the beam."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe.beam import node_coordinates
from ..fe.metrics import window_envelope
from ..fe.modes import contact_held_modes, nodal_field
from ..fe.quantities import metric_attrs


def _binned(t: np.ndarray, y: np.ndarray, edges: np.ndarray):
    """Per-bin (min, max, mean) of y over time bins (empty bins -> NaN)."""
    idx = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, edges.size - 2)
    nb = edges.size - 1
    cnt = np.bincount(idx, minlength=nb).astype(float)
    mean = np.bincount(idx, weights=y, minlength=nb) / np.where(cnt > 0, cnt, np.nan)
    lo = np.full(nb, np.inf)
    hi = np.full(nb, -np.inf)
    np.minimum.at(lo, idx, y)
    np.maximum.at(hi, idx, y)
    lo[cnt == 0] = np.nan
    hi[cnt == 0] = np.nan
    return lo, hi, mean


def detail_mask(t: np.ndarray, windows) -> np.ndarray:
    keep = np.zeros(t.size, bool)
    for a, b in windows:
        keep |= (t >= a) & (t <= b)
    return keep


def default_windows(duration: float, span: float = 0.005) -> list:
    """Full-resolution windows kept in the dataset: the start (drop / first stick) and the end."""
    span = min(span, duration / 2)
    return [[0.0, span], [duration - span, duration]]


SERIES = {
    # name: (units, long_name)
    "horizontal_displacement": ("mm", "horizontal displacement of node 1 from its initial position"),
    "vertical_displacement": ("mm", "vertical displacement of node 1 from its initial position"),
    "horizontal_velocity": ("mm s-1", "horizontal velocity of node 1"),
    "vertical_velocity": ("mm s-1", "vertical velocity of node 1"),
    "normal_force": ("N", "contact normal force"),
    "friction_force": ("N", "friction force on the beam along the disc velocity"),
    "slip_velocity": ("mm s-1", "beam minus disc tangential velocity at the contact point"),
    "midspan_horizontal_displacement": (
        "mm",
        "horizontal displacement of the mid-span node (off the contact) from its initial position",
    ),
    "midspan_horizontal_velocity": ("mm s-1", "horizontal velocity of the mid-span node (off the contact)"),
    "midspan_vertical_displacement": (
        "mm",
        "vertical displacement of the mid-span node (off the contact) from its initial position",
    ),
    "midspan_vertical_velocity": ("mm s-1", "vertical velocity of the mid-span node (off the contact)"),
}

#: series stored per time bin (min, max, mean) over the whole run
BINNED = (
    "horizontal_displacement",
    "vertical_displacement",
    "horizontal_velocity",
    "vertical_velocity",
    "midspan_horizontal_displacement",
    "midspan_horizontal_velocity",
    "midspan_vertical_displacement",
    "midspan_vertical_velocity",
    "normal_force",
)


def _series(r) -> dict:
    out = {
        "horizontal_displacement": r.x - r.x[0],
        "vertical_displacement": r.y - r.y[0],
        "horizontal_velocity": r.vx,
        "vertical_velocity": r.vy,
        "normal_force": r.normal_force,
        "friction_force": r.friction_force,
        "slip_velocity": r.slip_velocity,
    }
    zeros = (np.zeros_like(r.t), np.zeros_like(r.t))
    for comp in ("horizontal", "vertical"):
        x, v = r.extra.get("midspan", {}).get(comp, zeros)
        out[f"midspan_{comp}_displacement"] = x
        out[f"midspan_{comp}_velocity"] = v
    return out


def result_dataset(r, m: Mapping, *, windows=None, bin_width: float = 1e-4) -> xr.Dataset:
    """Trajectory -> dataset: full-resolution samples only inside ``windows`` (dimension ``time``), and
    per-bin min/max/mean plus stick/slip/separation fractions over the whole run (``bin_time``), so that
    a 1 s run at >= 20 samples per 12.9 kHz period is stored and drawn without aliasing. Scalars ``m``
    become scalar variables (units from stickslip.fe.quantities)."""
    t = r.t
    windows = windows if windows is not None else default_windows(float(t[-1]))
    keep = detail_mask(t, windows)
    ser = _series(r)
    data: dict = {}
    for k, (u, ln) in SERIES.items():
        data[k] = cf_variable("time", ser[k][keep], u, ln)
    data["contact_state"] = cf_variable(
        "time",
        r.state[keep].astype("i1"),
        "1",
        "contact state",
        flag_values=np.array([0, 1, 2], "i1"),
        flag_meanings="separated stick slip",
    )
    edges = np.arange(0.0, t[-1] + bin_width, bin_width)
    if edges.size < 2:
        edges = np.array([0.0, t[-1]])
    for k in BINNED:
        u, ln = SERIES[k]
        for stat, what, values in zip(
            ("min", "max", "mean"), ("minimum", "maximum", "mean"), _binned(t, ser[k], edges)
        ):
            data[f"{k}_{stat}"] = cf_variable("bin_time", values, u, f"{what} per bin of the {ln}")
    for code, name in enumerate(("separation", "stick", "slip")):
        _, _, frac = _binned(t, (r.state == code).astype(float), edges)
        data[f"{name}_fraction_per_bin"] = cf_variable(
            "bin_time", frac, "1", f"fraction of output samples in {name} per bin"
        )
    tw = window_envelope(t, r.vx)[0]
    for k in ("horizontal_velocity", "vertical_velocity", "horizontal_displacement", "vertical_displacement"):
        data[f"{k}_envelope"] = cf_variable(
            "window",
            window_envelope(t, ser[k])[1],
            SERIES[k][0],
            f"half peak-to-peak {k.replace('_', ' ')} per window",
        )
    if "first_mode_amplitude" in r.extra:
        mode_window_time, amp = r.extra["first_mode_amplitude"]
        data["first_mode_amplitude"] = cf_variable(
            "mode_window", amp, "mm", "horizontal amplitude of the first contact-held mode at node 1"
        )
    else:
        mode_window_time = np.zeros(0)
    data["detail_windows"] = cf_variable(
        ("detail_window", "bound"),
        np.array(windows, float),
        "s",
        "start and end of the full-resolution windows",
    )
    for k, v in m.items():
        data[k] = ((), float(v), metric_attrs(k, k.replace("_", " ")))
    # One constructor call: assigning ~40 variables one by one re-aligns the whole dataset each time
    # (2.6 s of a 6 s FE reading job).
    return xr.Dataset(
        data,
        coords={
            "time": cf_variable("time", t[keep], "s", "time (full-resolution windows only)"),
            "bin_time": cf_variable("bin_time", 0.5 * (edges[:-1] + edges[1:]), "s", "bin centre"),
            "window_time": cf_variable("window", tw, "s", "window centre time"),
            "mode_window_time": cf_variable(
                "mode_window", mode_window_time, "s", "centre of the first-mode demodulation window"
            ),
        },
    )


#: modes whose frequency and shape a scene dataset keeps
N_SHAPE_MODES = 10


def shape_variables(scene, q_static: np.ndarray) -> dict:
    """Along the beam (``node_position``): the static deflection in contact and the first modes with the
    contact held (shapes scaled so that their largest nodal displacement is +1), for
    the paper's Figs. 22 and 31 (mode shape, deflected beam)."""
    freq, phi = contact_held_modes(scene, N_SHAPE_MODES)
    x = node_coordinates(scene.params.beam.length, scene.params.beam.n_elements)
    shapes = {
        c: np.array([nodal_field(scene, phi[:, k], i) for k in range(freq.size)])
        for c, i in (("horizontal", 0), ("vertical", 1))
    }
    scale = np.maximum(np.abs(shapes["horizontal"]).max(axis=1), np.abs(shapes["vertical"]).max(axis=1))
    both = np.concatenate([shapes["horizontal"], shapes["vertical"]], axis=1)
    sign = np.sign(both[np.arange(freq.size), np.abs(both).argmax(axis=1)])
    out = {
        "node_position": cf_variable(
            "node_position", x, "mm", "position of the node along the beam from the clamp"
        ),
        "natural_frequency": cf_variable("mode", freq, "Hz", "natural frequencies with contact held"),
    }
    for c in ("horizontal", "vertical"):
        out[f"static_deflection_{c}"] = cf_variable(
            "node_position",
            nodal_field(scene, q_static, 0 if c == "horizontal" else 1),
            "mm",
            f"{c} displacement of the beam axis in the static equilibrium in contact",
        )
        out[f"mode_shape_{c}"] = cf_variable(
            ("mode", "node_position"),
            shapes[c] * (sign / np.where(scale > 0, scale, 1.0))[:, None],
            "1",
            f"{c} component of the mode shape with contact held (largest = 1)",
        )
    return out
