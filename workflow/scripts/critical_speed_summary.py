"""Thin wiring: the critical belt speed of every reading as CSV + netCDF + figure (Snakemake script)."""

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

from stickslip.io.netcdf import read_dataset, write_dataset  # noqa: E402
from stickslip.presentation.plots import critical_speed_figure  # noqa: E402
from stickslip.studies.ranking import reading_dataset  # noqa: E402

readings = list(snakemake.params.readings)
data = {r: read_dataset(p) for r, p in zip(readings, snakemake.input)}


def verdict(ds):
    vc = float(ds.critical_belt_speed)
    if np.isnan(vc):
        return (
            "undetermined: every run failed or diverged"
            if np.all(ds.solver_ok.values != 1)
            else "undetermined: runs faster than the last sticking one diverge (friction falls without bound)"
        )
    if vc == 0:
        return "never sticks at any swept speed: no stick-slip to lose"
    if np.isinf(vc):
        return "still sticks at the fastest swept speed: no critical speed in range"
    return f"stick-slip disappears at V_b = {vc:.3g} mm/s"


rows = [
    (
        r,
        float(ds.critical_belt_speed),
        float(ds.steady_sliding_stable_from),
        int(np.sum(ds.solver_ok.values != 1)),
        verdict(ds),
    )
    for r, ds in data.items()
]
with open(snakemake.output.csv, "w") as fh:
    fh.write("reading,critical_belt_speed_mm_per_s,steady_sliding_stable_from_mm_per_s,failed_runs,verdict\n")
    for r in rows:
        fh.write(f'{r[0]},{r[1]:.4g},{r[2]:.4g},{r[3]},"{r[4]}"\n')
out = reading_dataset(
    readings,
    "reading of the paper",
    {
        "critical_belt_speed": (
            [r[1] for r in rows],
            {"units": "mm s-1", "long_name": "critical belt speed"},
        ),
        "steady_sliding_stable_from": (
            [r[2] for r in rows],
            {"units": "mm s-1", "long_name": "steady sliding linearly stable from"},
        ),
        "failed_runs": ([r[3] for r in rows], {"units": "1", "long_name": "failed or diverging runs"}),
        "verdict": (np.array([r[4] for r in rows], dtype=object), {"long_name": "verdict"}),
    },
)
write_dataset(
    out,
    snakemake.output.nc,
    scene={"name": "critical_speed"},
    interpretation="all readings",
    method={"name": "exact continuation"},
    title="Critical belt speed per reading",
)
critical_speed_figure(data).savefig(snakemake.output.png, dpi=100)
