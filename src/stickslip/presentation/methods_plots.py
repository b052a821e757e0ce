"""Plotting for the methods study (used by the figure script and the notebook; presentation only)."""

from __future__ import annotations

import json
from itertools import product

import matplotlib.colors
import matplotlib.pyplot as plt
import numpy as np

FAILURE_COLORS = {
    "none": "#2ca02c",
    "creep": "#bcbd22",
    "chatter": "#ff7f0e",
    "missed_stick": "#9467bd",
    "step_collapse": "#d62728",
    "diverged": "#000000",
}


def family(solver: str, settings_json: str) -> str:
    s = json.loads(settings_json)
    tags = [str(s[k]) for k in ("method", "regularization") if k in s]
    if "theta" in s:
        tags.append(f"theta={s['theta']}")
    return solver + (" " + " ".join(tags) if tags else "")


def work_precision_figure(ds, title: str):
    """Error (state and period) vs CPU time and vs RHS evaluations; successful runs only."""
    ok = ds["status"].values == "ok"
    fams = [family(s, j) for s, j in zip(ds["solver"].values, ds["settings"].values)]
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    floor = 1e-16
    colors = {f: plt.cm.tab10(i % 10) for i, f in enumerate(dict.fromkeys(fams))}  # same colour per panel
    for (err, xkey), ax in zip(
        product(("state", "period_error"), ("cpu_time", "rhs_evaluations")), axes.flat
    ):
        for fam in dict.fromkeys(fams):
            idx = [i for i, f in enumerate(fams) if f == fam and ok[i]]
            if not idx:
                continue
            x = ds[xkey].values[idx]
            y = np.maximum(ds[err].values[idx], floor)
            if xkey == "rhs_evaluations" and fam == "exact":
                continue  # the exact solver evaluates no right-hand side
            order = np.argsort(x)
            ax.loglog(x[order], y[order], "o-", label=fam, ms=5, color=colors[fam])
        ax.set_xlabel(
            {"cpu_time": "CPU time [s] (min of repeats)", "rhs_evaluations": "RHS evaluations"}[xkey]
        )
        ax.set_ylabel({"state": "state error (max, relative)", "period_error": "relative period error"}[err])
        ax.grid(True, which="both", alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    n_fail = int((~ok).sum())
    fig.suptitle(
        f"{title}  ({n_fail} failed runs not plotted; see failure map)"
        + ("\nexact: error 0 by definition, drawn at 1e-16" if "exact" in fams else "")
    )
    fig.tight_layout()
    return fig


def failure_map_figure(ds):
    kinds = list(FAILURE_COLORS)
    fk = ds["failure_kind"].values  # (parameter, run)
    code = np.vectorize(kinds.index)(fk)
    fig, ax = plt.subplots(figsize=(8, 0.35 * ds.sizes["run"] + 2))
    cmap = matplotlib.colors.ListedColormap([FAILURE_COLORS[k] for k in kinds])
    ax.imshow(code.T, cmap=cmap, vmin=-0.5, vmax=len(kinds) - 0.5, aspect="auto")
    ax.set_xticks(range(ds.sizes["parameter"]), [f"{v:g}" for v in ds["parameter"].values])
    ax.set_yticks(range(ds.sizes["run"]), ds["label"].values, fontsize=7)
    ax.set_xlabel(ds.attrs.get("swept_parameter", "parameter"))
    for i, j in np.ndindex(code.shape):
        colour = "white" if fk[i, j] in ("diverged", "step_collapse") else "black"
        ax.text(i, j, fk[i, j], ha="center", va="center", fontsize=6, color=colour)
    ax.set_title("Where methods fail (classification against the exact solver)")
    fig.tight_layout()
    return fig
