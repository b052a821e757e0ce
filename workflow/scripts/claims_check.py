"""Thin wiring: fail the build when a measured claim status differs from the one pinned in its row, or when a
decision flips as the claimed metrics move within their perturbation-ensemble range."""

import contextlib
import sys

from stickslip.claims.flips import flipped_decisions
from stickslip.claims.models import annotate, read_comparison
from stickslip.claims.table import main
from stickslip.io.netcdf import read_dataset

inp = snakemake.input  # noqa: F821 (injected by Snakemake)
with open(snakemake.log[0], "w") as log, contextlib.redirect_stdout(log):  # noqa: F821
    code = main(["check", inp.table])
    # as the claims table: rows the beam may not decide (the model comparison) stay undecided
    claims = annotate(snakemake.params.claims, read_comparison(inp.comparison), snakemake.params.cross_scene)
    flipped = flipped_decisions(claims, snakemake.params.readings, read_dataset)  # noqa: F821
    for line in flipped:
        print(f"FLIPS {line}: the decision rests on digits below the numerical noise")
    print(f"{len(flipped)} decisions flip within their ensemble spread")
if code or flipped:
    sys.stderr.write(open(snakemake.log[0]).read())  # noqa: F821
    sys.exit(1)
