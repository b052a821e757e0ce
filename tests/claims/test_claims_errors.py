"""The repository's claims rows pass every check (stickslip.claims), and broken rows are rejected naming the
file, the row and the key: alone, against the config, and against the pinned claim ids."""

import math

import pytest
import yaml
from bad_inputs import BAD_CLAIMS, BAD_CLAIMS_IN_CONTEXT, VALUE_ROW, _with, base_config

from stickslip.claims.load import ClaimsError, check_claims, load_claims
from stickslip.claims.rows import Claim

from project_run import ROOT


def _pinned_ids():
    from stickslip.claims.load import load_claims as load

    text = (ROOT / "config" / "claims" / "ids.txt").read_text()
    pinned = [ln.strip() for ln in text.splitlines() if ln.strip() and not ln.startswith("#")]
    assert sorted(pinned) == sorted(c.id for c in load(sorted((ROOT / "config" / "claims").glob("*.yaml"))))
    return pinned


@pytest.mark.parametrize("case", sorted(BAD_CLAIMS_IN_CONTEXT))
def test_claims_rows_that_contradict_the_config_or_the_pins_are_rejected(case, tmp_path):
    rows, words = BAD_CLAIMS_IN_CONTEXT[case]
    (tmp_path / "zz_broken.yaml").write_text(yaml.safe_dump(rows))
    claims = load_claims(sorted((ROOT / "config" / "claims").glob("*.yaml")) + [tmp_path / "zz_broken.yaml"])
    config = base_config()
    readings = list(config["onedof"]["readings"]) + list(config["fe"]["readings"])
    with pytest.raises(ClaimsError) as info:
        check_claims(claims, config["claims"]["readings"], known_readings=readings, pinned_ids=_pinned_ids())
    for word in words:
        assert word in str(info.value), f"{case}: message does not name {word!r}: {info.value}"


def test_a_claimed_variable_that_its_run_dataset_never_holds_is_rejected(tmp_path):
    from stickslip.catalogue import onedof_catalogue
    from stickslip.io.run_variables import run_dataset_variables

    (tmp_path / "zz_broken.yaml").write_text(yaml.safe_dump([_with(VALUE_ROW, variable="max_displacment")]))
    claims = load_claims([tmp_path / "zz_broken.yaml"])
    catalogue = onedof_catalogue(base_config()["onedof"])
    with pytest.raises(ClaimsError, match=r"zz_broken.yaml: claim zz_value: variable: 'max_displacment'"):
        check_claims(
            claims,
            ["consistent_caption"],
            producible=lambda path: True,
            variables_of=lambda path: run_dataset_variables() if path in catalogue else None,
        )


def test_every_variable_a_run_dataset_holds_is_in_the_registry():
    from stickslip.io.run_variables import run_dataset_variables
    from stickslip.schema import Onedof
    from stickslip.studies.onedof import scene_run_dataset
    from stickslip.studies.specs import run_spec

    onedof = Onedof.model_validate(base_config()["onedof"])
    ds = scene_run_dataset(run_spec(onedof, "fig02", "consistent_caption", "exact"))
    assert set(map(str, ds.data_vars)) <= run_dataset_variables()
    assert "max_displacement" in ds and "belt_velocity" in ds


def test_a_deleted_claims_file_names_the_ids_it_lost():
    files = sorted((ROOT / "config" / "claims").glob("*.yaml"))
    kept = [f for f in files if f.name != "section_06_deceleration.yaml"]
    with pytest.raises(ClaimsError, match=r"pinned but not found.*s6_"):
        check_claims(load_claims(kept), ["consistent_caption"], pinned_ids=_pinned_ids())


def test_the_repository_claims_pass_every_check():
    config = base_config()
    readings = list(config["onedof"]["readings"]) + list(config["fe"]["readings"])
    claims = load_claims(sorted((ROOT / "config" / "claims").glob("*.yaml")))
    assert len(claims) >= 10
    assert all(isinstance(c, Claim) and c.file.endswith(".yaml") for c in claims)
    assert all(math.isfinite(c.value) for c in claims if c.kind == "value")
    check_claims(claims, config["claims"]["readings"], known_readings=readings, pinned_ids=_pinned_ids())


@pytest.mark.parametrize("case", sorted(BAD_CLAIMS))
def test_broken_claims_row_is_rejected_naming_the_row_and_key(case, tmp_path):
    rows, words = BAD_CLAIMS[case]
    (tmp_path / "zz_broken.yaml").write_text(yaml.safe_dump(rows))
    with pytest.raises(ValueError) as info:
        load_claims(sorted((ROOT / "config" / "claims").glob("*.yaml")) + [tmp_path / "zz_broken.yaml"])
    for word in words:
        assert word in str(info.value), f"{case}: message does not name {word!r}: {info.value}"
    assert "zz_broken.yaml" in str(info.value), f"{case}: message does not name the file: {info.value}"
