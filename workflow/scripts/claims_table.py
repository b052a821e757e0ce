"""Thin wiring: evaluate every claim row against the datasets and write the deviations table."""

from functools import lru_cache

from stickslip.io.claims import evaluate_all, load_claims, write_table
from stickslip.io.netcdf import read_dataset

open_dataset = lru_cache(maxsize=None)(read_dataset)
results = evaluate_all(load_claims(snakemake.input.claims), snakemake.params.readings, open_dataset)
write_table(results, snakemake.output.csv, snakemake.output.md)
