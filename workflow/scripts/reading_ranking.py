"""Thin wiring: the interpretation study - readings ranked by the claims they reproduce (Snakemake script)."""

import numpy as np
import xarray as xr

from stickslip.claims.table import read_table
from stickslip.io.netcdf import write_dataset
from stickslip.studies.ranking import COLUMNS, rank_readings, unreproduced_claims

rows = read_table(snakemake.input[0])
table = rank_readings(rows, list(snakemake.params.readings))
cols = list(COLUMNS)  # one count column per claim status
with open(snakemake.output.csv, "w") as fh:
    fh.write(",".join(cols) + "\n")
    for t in table:
        fh.write(",".join(f"{t[c]:.3f}" if isinstance(t[c], float) else str(t[c]) for c in cols) + "\n")
print(open(snakemake.output.csv).read())
unrep = unreproduced_claims(rows, list(snakemake.params.readings))
with open(snakemake.output.unreproduced, "w", newline="") as fh:
    import csv

    w = csv.DictWriter(fh, fieldnames=["claim", "figure", "statuses", "why", "quote"])
    w.writeheader()
    w.writerows(unrep)
ds = xr.Dataset(
    {
        c.replace("-", "_"): (  # netCDF/CF names: letters, digits, underscores
            "reading",
            np.array([t[c] for t in table], dtype=float if c.startswith("reproduced_f") else np.int32),
            {
                "units": "1",
                "long_name": f"number of claim checks: {c}"
                if c != "reproduced_fraction_of_comparable"
                else "reproduced / (reproduced + deviates)",
            },
        )
        for c in cols[1:]
    },
    coords={
        # an auxiliary (non-dimension) coordinate: CF wants dimension coordinates numeric and monotonic
        "reading_name": (
            "reading",
            np.array([t["reading"] for t in table], dtype=object),
            {"long_name": "reading of the paper's equations, best first"},
        ),
        "rank": (
            "reading",
            np.arange(1, len(table) + 1, dtype=np.int32),
            {"units": "1", "long_name": "rank"},
        ),
    },
)
ds.attrs["claims_no_reading_reproduces"] = len(unrep)
write_dataset(
    ds,
    snakemake.output.nc,
    scene={"name": "interpretation_study"},
    interpretation="all readings",
    method={"name": "claims check"},
    title="Readings ranked by reproduced claims",
)
