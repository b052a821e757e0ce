"""Thin wiring: Fig. 4, Eq. 6 as printed and dimensionally correct, peaks in closed form."""

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

from stickslip.io.netcdf import write_dataset  # noqa: E402
from stickslip.io.scenes import run_spec  # noqa: E402
from stickslip.model.amplitude import amplitude_correct, amplitude_printed, correct_peak, printed_peak  # noqa: E402
from stickslip.model.params import effective_mass  # noqa: E402
from stickslip.plots import eq6_figure  # noqa: E402

config = snakemake.params.config
cfg = config["onedof"]["eq6"]
spec = run_spec(config, "fig02", "consistent_caption", "exact")
p = spec.params
force = p.mu_s * p.normal_force
f = np.linspace(0.0, float(cfg["f_max"]), int(cfg["points"]))
w = 2 * np.pi * f
fp, ap = printed_peak(force, p.stiffness, p.damping)
fc, ac = correct_peak(force, p.stiffness, p.damping, p.mass)
fs, as_ = correct_peak(force, p.stiffness, p.damping, effective_mass(p.mass, "si"))
scalar = lambda v, u, n: ((), float(v), {"units": u, "long_name": n})  # noqa: E731
ds = xr.Dataset(
    {
        "amplitude_printed": (
            "frequency",
            amplitude_printed(w, force, p.stiffness, p.damping),
            {"units": "mm", "long_name": "Eq. 6 as printed: F/sqrt((K-w^2)^2 + c w^2)"},
        ),
        "amplitude_correct": (
            "frequency",
            amplitude_correct(w, force, p.stiffness, p.damping, p.mass),
            {"units": "mm", "long_name": "1-DOF: F/sqrt((K-M w^2)^2 + (C w)^2)"},
        ),
        "peak_frequency_printed": scalar(fp, "Hz", "peak of Eq. 6 as printed (w^2 = K - c/2)"),
        "peak_amplitude_printed": scalar(ap, "mm", "peak amplitude of Eq. 6 as printed"),
        "peak_frequency_correct": scalar(fc, "Hz", "resonance of the 1-DOF curve (w^2 = K/M - C^2/2M^2)"),
        "peak_amplitude_correct": scalar(ac, "mm", "peak amplitude of the 1-DOF curve"),
        "peak_frequency_correct_si": scalar(
            fs, "Hz", "resonance with M converted to N s^2/mm (0: overdamped, no peak)"
        ),
        "peak_amplitude_correct_si": scalar(as_, "mm", "peak amplitude with M converted to N s^2/mm"),
        "force": scalar(force, "N", "F = mu_s N assumed for 'the friction force' of Eq. 6"),
    },
    coords={"frequency": ("frequency", f, {"units": "Hz", "long_name": "excitation frequency w / 2 pi"})},
)
write_dataset(
    ds,
    snakemake.output.nc,
    scene=spec.scene_attrs(),
    interpretation={
        "equation": "Eq. 6 as printed and dimensionally correct",
        "force": cfg.get("force", "mu_s N"),
        "units": "as_given (and si for the *_si peak)",
    },
    method={"name": "closed form"},
    title="Fig. 4: frequency-amplitude curve of Eq. 6",
)
eq6_figure(ds).savefig(snakemake.output.png, dpi=110)
