"""The claims check on the real configuration: every pinned status must still be what the pipeline measures.

Builds (or reuses) the repository's own results/ up to the deviations table.
"""

import pytest

from stickslip.claims.table import read_table, unexpected

from project_run import build_claims_table, decisions_flipped_within_spread


@pytest.mark.pipeline
def test_claim_statuses_match_their_pins(repo_root, tmp_path_factory):
    rows = read_table(build_claims_table(repo_root, tmp_path_factory))
    changed = [
        f"{r['claim']} [{r['reading']}]: {r['status']} (pinned {r['expected']}; {r['reason']})"
        for r in unexpected(rows)
    ]
    assert not changed, "claim statuses changed without updating their pins:\n" + "\n".join(changed)


@pytest.mark.pipeline
def test_no_decided_claim_flips_when_its_measurements_move_within_their_spread(repo_root, tmp_path_factory):
    """Every measured value moved to the end of its perturbation-ensemble range: no reproduced claim becomes
    deviating or the reverse (those within 3 spreads of their threshold are pinned indistinguishable)."""
    build_claims_table(repo_root, tmp_path_factory)
    flipped = decisions_flipped_within_spread(repo_root)
    assert not flipped, "decisions that rest on digits below the numerical noise:\n" + "\n".join(flipped)
