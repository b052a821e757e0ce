import pytest

from project_run import ROOT


@pytest.fixture(scope="session")
def repo_root():
    return ROOT
