"""Thin wiring: every paper figure's verdicts -> results/claims/figure_verdicts.csv."""

import yaml

from stickslip.claims.table import read_table
from stickslip.claims.verdicts import figure_table
from stickslip.io.progress import log_to_file
from stickslip.io.text_files import write_csv_atomic
from stickslip.studies.ranking import rank_readings

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
params = snakemake.params  # noqa: F821
deviations = read_table(snakemake.input.deviations)  # noqa: F821
# ties between equally good readings follow the interpretation study's ranking
order = [t["reading"] for t in rank_readings(deviations, sorted({r["reading"] for r in deviations} - {""}))]
rows = figure_table(
    yaml.safe_load(open(snakemake.input.paper)),  # noqa: F821
    deviations,
    params.claims,
    params.primary,
    params.printed,
    params.fe_primary,
    read_table(snakemake.input.fe_readings),  # noqa: F821
    order,
    params.alternative,
)
write_csv_atomic(snakemake.output[0], rows, lineterminator="\r\n")  # noqa: F821
