"""Every FE claim under every FE reading -> results/fe/readings_claims.csv (the claims table checks the
default reading; here its dataset paths are re-pointed at each reading's datasets)."""

import csv
from dataclasses import asdict
from functools import lru_cache

from stickslip.claims.load import load_claims
from stickslip.claims.models import annotate, read_comparison
from stickslip.claims.per_reading import claims_per_reading
from stickslip.io.netcdf import read_dataset
from stickslip.io.progress import log_to_file

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
# the model comparison (default reading) decides which model may decide a row, in every reading alike
comparison = read_comparison(snakemake.input.comparison)  # noqa: F821
claims = annotate(load_claims([snakemake.input.claims]), comparison)  # noqa: F821
results = claims_per_reading(
    claims,
    snakemake.params.readings,
    snakemake.params.default,
    lru_cache(maxsize=None)(read_dataset),  # noqa: F821
)
rows = [asdict(r) for r in results]
with open(snakemake.output[0], "w", newline="") as f:  # noqa: F821
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
