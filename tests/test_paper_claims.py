"""The claims check on the real configuration: every pinned status must still be what the pipeline measures.

Builds (or reuses) the repository's own results/ up to the deviations table.
"""

import pytest

from stickslip.io.claims import read_table, unexpected

from project_run import run_snakemake


@pytest.mark.pipeline
def test_claim_statuses_match_their_pins(repo_root):
    run_snakemake(repo_root, "results/claims/deviations.csv", timeout=3000)
    rows = read_table(repo_root / "results" / "claims" / "deviations.csv")
    changed = [
        f"{r['claim']} [{r['reading']}]: {r['status']} (pinned {r['expected']}; {r['reason']})"
        for r in unexpected(rows)
    ]
    assert not changed, "claim statuses changed without updating their pins:\n" + "\n".join(changed)
