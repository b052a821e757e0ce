"""The claims check on the real configuration: every pinned status must still be what the pipeline measures.

Builds (or reuses) the repository's own results/ up to the deviations table.
"""

import pytest

from stickslip.io.claims import read_table, unexpected

from project_run import decisions_flipped_within_spread, run_snakemake

# Both tests run Snakemake in the repository's own results/: never at once (`make test` runs -n 2).
pytestmark = pytest.mark.xdist_group("repo_results")


@pytest.mark.pipeline
def test_claim_statuses_match_their_pins(repo_root):
    run_snakemake(repo_root, "results/claims/deviations.csv", timeout=3000)
    rows = read_table(repo_root / "results" / "claims" / "deviations.csv")
    changed = [
        f"{r['claim']} [{r['reading']}]: {r['status']} (pinned {r['expected']}; {r['reason']})"
        for r in unexpected(rows)
    ]
    assert not changed, "claim statuses changed without updating their pins:\n" + "\n".join(changed)


@pytest.mark.pipeline
def test_no_decided_claim_flips_when_its_measurements_move_within_their_spread(repo_root):
    """Every measured value moved to the end of its perturbation-ensemble range: no reproduced claim becomes
    deviating or the reverse (those within 3 spreads of their threshold are pinned indistinguishable)."""
    run_snakemake(repo_root, "results/claims/deviations.csv", timeout=3000)
    flipped = decisions_flipped_within_spread(repo_root)
    assert not flipped, "decisions that rest on digits below the numerical noise:\n" + "\n".join(flipped)
