import pytest
import yaml

from stickslip.inverse.problem import load_claim_rows

from project_run import ROOT


# The inverse study's tests read the repository's own configuration and claims (a copy per module: a test
# may change its config).
@pytest.fixture(scope="module")
def config():
    cfg = {}
    for name in ("config.yaml", "inverse.yaml"):
        cfg.update(yaml.safe_load((ROOT / "config" / name).read_text()))
    return cfg


@pytest.fixture(scope="module")
def claims():
    return load_claim_rows(sorted((ROOT / "config" / "claims").glob("*.yaml")))
