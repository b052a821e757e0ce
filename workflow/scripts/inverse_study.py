"""Thin wiring of rule inverse_study: run the whole inverse study and write results/inverse/."""

import glob
from pathlib import Path

from stickslip.inverse.outputs import write_study
from stickslip.inverse.problem import load_claim_rows
from stickslip.inverse.study import run_study
from stickslip.schema import InverseJob

job = InverseJob.model_validate(snakemake.params.config)  # noqa: F821 (injected by Snakemake)
claims = load_claim_rows(sorted(glob.glob(job.inverse.claims_glob)))
out = run_study(job, claims)
write_study(out, Path(snakemake.output.summary).parent)  # noqa: F821
