"""Thin wiring: evaluate every claim row against the datasets and write the deviations table."""

from functools import lru_cache

from stickslip.claims.evaluate import evaluate_all
from stickslip.claims.models import annotate, read_comparison
from stickslip.claims.table import write_table
from stickslip.io.netcdf import read_dataset

open_dataset = lru_cache(maxsize=None)(read_dataset)
# a beam-on-disc row decided by the beam where the model comparison disagrees is not decided (claim_models)
comparison = read_comparison(snakemake.input.comparison)  # noqa: F821
# the claim rows as the parse read them (common.smk): no job parses the claims files again
claims = annotate(snakemake.params.claims, comparison, snakemake.params.cross_scene)  # noqa: F821
results = evaluate_all(claims, snakemake.params.readings, open_dataset)  # noqa: F821
write_table(results, snakemake.output.csv, snakemake.output.md)
