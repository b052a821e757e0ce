"""Write the study: one netCDF per figure (atomic, with provenance), summary / hypotheses / ranking / numbers
/ conflicts CSVs, corner plots of the sampled regions."""

from __future__ import annotations

import csv
import io
from pathlib import Path

import numpy as np

from ..catalogue import INVERSE_TABLES
from ..io.netcdf import write_dataset
from ..io.text_files import write_text_atomic
from .dataset import INTERPRETATION


def write_csv(rows: list[dict], path) -> Path:
    """Rows as CSV (the union of their keys as columns, in first-seen order), written atomically."""
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=list(dict.fromkeys(k for row in rows for k in row)))
    writer.writeheader()
    writer.writerows(rows)
    return write_text_atomic(path, buf.getvalue())


def corner_plot(ds, family: str, path) -> Path:
    """Corner plot of one family's samples (log10 of the free parameters), stated set and best fit marked."""
    import corner
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    sub = ds.sel(family=family)
    free = [str(p) for p in sub.parameter.values if np.isfinite(sub[f"fit_point_{p}"])]
    samples = np.log10(np.column_stack([sub[f"samples_{p}"].values for p in free]))
    samples = samples[np.all(np.isfinite(samples), axis=1)]
    labels = [f"log10 {sub.parameter_symbol.sel(parameter=p).item()}" for p in free]
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    stated = np.log10([float(sub[f"stated_{p}"]) for p in free])
    best = np.log10([float(sub[f"fit_point_{p}"]) for p in free])
    if len(samples) <= len(free):
        fig, ax = plt.subplots(figsize=(6, 2))
        steps = float(sub.chain_steps)
        text = "not sampled in this build" if not np.isfinite(steps) else "no feasible parameter set sampled"
        ax.text(0.5, 0.5, text, ha="center", va="center")
        ax.set_axis_off()
    else:
        fig = corner.corner(
            samples,
            labels=labels,
            truths=stated,
            truth_color="tab:red",
            plot_datapoints=True,
            plot_density=False,
            plot_contours=False,
            data_kwargs={"alpha": 0.3, "ms": 2},
            hist_kwargs={"color": "0.3"},
            range=_ranges(samples, stated, best),
        )
        corner.overplot_points(fig, best[None, :], marker="x", color="tab:blue", ms=8)
    verdict = "consistent" if int(sub.consistent) else "inconsistent"
    fig.suptitle(
        f"FIT {ds.attrs['figure']} / {family}: {verdict} (worst |residual| {float(sub.worst_residual):.2f})\n"
        "red: stated, blue x: a best-fitting set (on a ridge: one member of it)",
        fontsize=10,
    )
    fig.savefig(path, dpi=60)
    plt.close(fig)
    return path


def _ranges(samples, stated, best, margin=0.05):
    """Axis ranges holding the samples, the stated set and the best fit (the distance is the point)."""
    lo = np.minimum(np.minimum(samples.min(0), stated), best)
    hi = np.maximum(np.maximum(samples.max(0), stated), best)
    return [(a - margin, b + margin) for a, b in zip(lo, hi)]


def write_study(out: dict, outdir) -> list[Path]:
    outdir = Path(outdir)
    written = []
    inverse = out["inverse"]
    scene = {"study": "inverse", "mode": inverse.mode}
    method = {
        "forward": "exact event-driven solver",
        "best_fit": "scipy.optimize.least_squares (trf, seeded multi-start)",
        "region": "emcee EnsembleSampler (seeded)",
        "identifiability": "rank from the equations (structure), ranges by profile likelihood (profile)",
        "conflicts": "minimal conflicting subsets by increasing size (conflicts)",
        **{k: v for k, v in inverse.settings_record.items() if k != "mode"},
    }
    for name, ds in out["datasets"].items():
        written.append(
            write_dataset(
                ds,
                outdir / f"{name}.nc",
                scene=scene,
                interpretation=INTERPRETATION,
                method=method,
                title=ds.attrs["title"],
            )
        )
        if name in inverse.mode_settings.corner:
            for family in ds.family.values:
                written.append(corner_plot(ds, str(family), outdir / "corner" / f"{name}_{family}.png"))
    return written + [write_csv(out[table], outdir / f"{table}.csv") for table in INVERSE_TABLES]
