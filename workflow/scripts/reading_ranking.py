"""Thin wiring: the interpretation study - readings ranked by the claims they reproduce (Snakemake script)."""

import numpy as np

from stickslip.claims.table import read_table
from stickslip.io.netcdf import write_dataset
from stickslip.io.text_files import write_csv_atomic
from stickslip.studies.ranking import COLUMNS, rank_readings, reading_dataset, unreproduced_claims

rows = read_table(snakemake.input[0])
table = rank_readings(rows, list(snakemake.params.readings))
cells = [{c: f"{v:.3f}" if isinstance(v, float) else v for c, v in t.items()} for t in table]
write_csv_atomic(snakemake.output.csv, cells, fields=list(COLUMNS))  # one count column per claim status
print(open(snakemake.output.csv).read())
unrep = unreproduced_claims(rows, list(snakemake.params.readings))
fields = ["claim", "figure", "statuses", "why", "quote"]
write_csv_atomic(snakemake.output.unreproduced, unrep, fields=fields, lineterminator="\r\n")
counts = {
    c.replace("-", "_"): (  # netCDF/CF names: letters, digits, underscores
        np.array([t[c] for t in table], dtype=float if c.startswith("reproduced_f") else np.int32),
        {
            "units": "1",
            "long_name": f"number of claim checks: {c}"
            if c != "reproduced_fraction_of_comparable"
            else "reproduced / (reproduced + deviates)",
        },
    )
    for c in COLUMNS[1:]
}
ds = reading_dataset([t["reading"] for t in table], "reading of the paper's equations, best first", counts)
ranks = np.arange(1, len(table) + 1, dtype=np.int32)
ds = ds.assign_coords(rank=("reading", ranks, {"units": "1", "long_name": "rank"}))
ds.attrs["claims_no_reading_reproduces"] = len(unrep)
write_dataset(
    ds,
    snakemake.output.nc,
    scene={"name": "interpretation_study"},
    interpretation="all readings",
    method={"name": "claims check"},
    title="Readings ranked by reproduced claims",
)
