"""Thin wiring: evaluate every claim row against the datasets and write the deviations table."""

from functools import lru_cache

from stickslip.io.claims import evaluate_all, load_claims, write_table
from stickslip.io.netcdf import open_lazily

# A claim reads a few scalars of a dataset that may hold long time series: read only what is used.
open_dataset = lru_cache(maxsize=None)(open_lazily)
claims = load_claims(snakemake.input.claims)  # noqa: F821
results = evaluate_all(claims, snakemake.params.readings, open_dataset)  # noqa: F821
write_table(results, snakemake.output.csv, snakemake.output.md)  # noqa: F821
