import pytest

from stickslip.model import PAPER_BASELINE, BeltModel


def scene(variant="consistent", **changes):
    return BeltModel.build(PAPER_BASELINE.with_(**changes), variant)


@pytest.fixture
def baseline05():
    return scene(sigma=0.5)


@pytest.fixture
def baseline03():
    return scene(sigma=0.3)
