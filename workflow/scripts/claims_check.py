"""Thin wiring: fail the build when a measured claim status differs from the one pinned in its row."""

import contextlib
import sys

from stickslip.claims.table import main

with open(snakemake.log[0], "w") as log, contextlib.redirect_stdout(log):  # noqa: F821 (injected by Snakemake)
    code = main(["check", snakemake.input[0]])  # noqa: F821
if code:
    sys.stderr.write(open(snakemake.log[0]).read())  # noqa: F821
    sys.exit(code)
