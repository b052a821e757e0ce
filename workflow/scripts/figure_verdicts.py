"""Thin wiring: every paper figure's verdicts -> results/claims/figure_verdicts.csv."""

import csv
import os

import yaml

from stickslip.claims.load import load_claims
from stickslip.claims.table import read_table
from stickslip.io.progress import log_to_file
from stickslip.presentation.verdicts import figure_table

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
params = snakemake.params  # noqa: F821
rows = figure_table(
    yaml.safe_load(open(snakemake.input.paper)),  # noqa: F821
    read_table(snakemake.input.deviations),  # noqa: F821
    load_claims(snakemake.input.claims),  # noqa: F821
    params.primary,
    params.printed,
    params.fe_primary,
    read_table(snakemake.input.fe_readings),  # noqa: F821
    params.alternative,
)
out = snakemake.output[0]  # noqa: F821
with open(out + ".tmp", "w", newline="") as fh:
    writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
os.replace(out + ".tmp", out)
