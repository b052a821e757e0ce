"""A results folder records the configuration that built it (stickslip.pipeline.results_owner)."""

import pytest

from stickslip.pipeline import results_owner


def test_overlays_are_the_config_files_beyond_the_projects_own_relative_to_the_project(tmp_path):
    (tmp_path / "config" / "test").mkdir(parents=True)
    own, small, outside = (
        tmp_path / "config/a.yaml",
        tmp_path / "config/test/a.yaml",
        tmp_path.parent / "x.yaml",
    )
    for p in (own, small):
        p.write_text("{}")
    assert results_owner.overlays([own, small, outside], tmp_path) == ["config/test/a.yaml", str(outside)]


def test_a_folder_without_a_record_or_with_the_same_configuration_is_accepted_and_another_refused(tmp_path):
    results_owner.check(tmp_path / "results", ["config/test/a.yaml"])  # nothing built yet
    results_owner.record(tmp_path / "results", [])
    results_owner.check(tmp_path / "results", [])
    with pytest.raises(
        results_owner.ForeignResultsError, match=r"config/\*\.yaml; this build is config/\*\.yaml"
    ):
        results_owner.check(tmp_path / "results", ["config/test/a.yaml"])
    with pytest.raises(SystemExit, match="make small"):
        results_owner.claim(tmp_path / "results", ["config/test/a.yaml"])
    assert results_owner.recorded(tmp_path / "results") == []
