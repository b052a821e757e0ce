import pytest
import yaml

from stickslip.inverse.problem import load_claim_rows
from stickslip.schema import InverseJob, InverseOnedof

from project_run import ROOT


def inverse_job(section: dict) -> InverseJob:
    """The inverse study's typed params from config sections, as its rule passes them."""
    return InverseJob.model_validate(
        {"onedof": InverseOnedof.part_of(section["onedof"]), "inverse": section["inverse"]}
    )


# The inverse study's tests read the repository's own configuration and claims.
@pytest.fixture(scope="module")
def config():
    sections = {}
    for name in ("config.yaml", "inverse.yaml"):
        sections.update(yaml.safe_load((ROOT / "config" / name).read_text()))
    return inverse_job(sections)


@pytest.fixture(scope="module")
def claims():
    return load_claim_rows(sorted((ROOT / "config" / "claims").glob("*.yaml")))
