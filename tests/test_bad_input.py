"""Broken inputs are rejected before any job runs, with a message naming the key, and nothing is written.

Every case is an override config merged over config/*.yaml and the small CI config, as a user's
``--configfile`` would be, or a broken claims file. The whole matrix goes through
``stickslip.config.validate_config`` in-process - the one function the Snakefile calls at parse time - and
a few cases of each kind also run the real pipeline (not a dry run) on a copy of the project: it must fail
at parse time, print the offending key, and leave no ``results/`` behind. Run with ``-s`` to see each
input and the last lines of its message.
"""

import shutil

import pytest
import yaml

from stickslip.config import load_config, merge, validate_config
from stickslip.io.claims import load_claims

from project_run import ROOT, copy_project, run_snakemake, small_config_args

P = "onedof.defaults.params"
CASES = {
    # id: (override config, words the message must contain)
    "mass_negative": ({"onedof": {"defaults": {"params": {"mass": -1.0}}}}, ["mass"]),
    "mass_zero": ({"onedof": {"defaults": {"params": {"mass": 0.0}}}}, ["mass"]),
    "stiffness_zero": ({"onedof": {"scenes": {"fig02": {"params": {"stiffness": 0.0}}}}}, ["stiffness"]),
    "stiffness_negative": ({"onedof": {"scenes": {"fig02": {"params": {"stiffness": -5.0}}}}}, ["stiffness"]),
    "stiffness_nan": (
        {"onedof": {"scenes": {"fig02": {"params": {"stiffness": float("nan")}}}}},
        ["stiffness"],
    ),
    "mass_inf": ({"onedof": {"defaults": {"params": {"mass": float("inf")}}}}, ["mass"]),
    "stiffness_string": ({"onedof": {"defaults": {"params": {"stiffness": "five"}}}}, ["stiffness", "five"]),
    "t_end_string": ({"onedof": {"defaults": {"t_end": "long"}}}, ["t_end"]),
    "t_end_nan": ({"onedof": {"defaults": {"t_end": float("nan")}}}, ["t_end"]),
    "readings_not_a_list": (
        {"onedof": {"figures": {"fig02": {"readings": "consistent_caption"}}}},
        ["readings"],
    ),
    "unknown_method": ({"onedof": {"figures": {"fig02": {"methods": ["exact", "rk99"]}}}}, ["rk99"]),
    "unknown_solver": ({"onedof": {"methods": {"ode45": {"solver": "nosuch"}}}}, ["nosuch"]),
    "unknown_scene": ({"onedof": {"figures": {"fig02": {"scene": "fig99"}}}}, ["fig99"]),
    "unknown_reading": ({"onedof": {"figures": {"fig02": {"readings": ["eq9_text"]}}}}, ["eq9_text"]),
    "unknown_claims_reading": ({"claims": {"readings": ["eq9_text"]}}, ["claims.readings", "eq9_text"]),
    "unknown_variant": ({"onedof": {"readings": {"eq3_text": {"variant": "eq5_printed"}}}}, ["variant"]),
    "missing_friction_table": (
        {"fe": {"friction_table": "results/onedof/no_such_table.csv"}},
        ["fe.friction_table", "no_such_table.csv"],
    ),
    "fe_negative_modulus": (
        {"fe": {"defaults": {"beam": {"youngs_modulus_gpa": -210.0}}}},
        ["youngs_modulus_gpa"],
    ),
    "fe_nan_t_end": ({"fe": {"defaults": {"solver": {"t_end": float("nan")}}}}, ["t_end"]),
    "fe_unknown_sweep_base": (
        {"fe": {"sweeps": {"angle_sweep": {"base": "no_scene"}}}},
        ["fe.sweeps.angle_sweep.base"],
    ),
    "methods_negative_mass": ({"methods_study": {"base_params": {"mass": -1.0}}}, ["mass"]),
    "methods_negative_eta": (
        {"methods_study": {"methods": [{"solver": "karnopp", "sweep": {"eta": [1.0e-3, -1.0]}}]}},
        ["methods_study.methods", "eta"],
    ),
    "ode45_negative_rtol": ({"onedof": {"methods": {"ode45": {"rtol": -1.0e-3}}}}, ["ode45", "rtol"]),
    "ensemble_bad_relative": ({"ensemble": {"relative": 0.5}}, ["ensemble", "relative"]),
}

BAD_CLAIMS = {
    "claims_missing_key": (
        [{"id": "x1", "section": "3", "figure": "Fig. 2", "kind": "value"}],
        ["x1", "missing key"],
    ),
    "claims_bad_kind": (
        [
            {
                "id": "x2",
                "section": "3",
                "figure": "Fig. 2",
                "quote": "q",
                "kind": "guess",
                "expected": "reproduced",
            }
        ],
        ["x2", "kind"],
    ),
    "claims_bad_status": (
        [
            {
                "id": "x3",
                "section": "3",
                "figure": "Fig. 2",
                "quote": "q",
                "kind": "value",
                "expected": "maybe",
            }
        ],
        ["x3", "maybe"],
    ),
}


#: Cases also run through the real pipeline: one schema error, one resolver error, one cross-section error.
END_TO_END = ("mass_negative", "ode45_negative_rtol", "missing_friction_table")


def base_config() -> dict:
    files = sorted((ROOT / "config").glob("*.yaml")) + sorted((ROOT / "config" / "test").glob("*.yaml"))
    return load_config(files)


@pytest.mark.parametrize("case", sorted(CASES))
def test_broken_config_is_rejected_naming_its_key(case):
    override, words = CASES[case]
    with pytest.raises(Exception) as info:  # noqa: B017 - schema errors are Snakemake's WorkflowError
        validate_config(merge(base_config(), override), producible=PRODUCIBLE)
    text = str(info.value)
    print(f"\n[{case}] {override}\n{text[-600:]}")
    for word in words:
        assert word in text, f"{case}: message does not name {word!r}:\n{text[-3000:]}"


def test_the_repository_config_passes():
    validate_config(base_config(), producible=PRODUCIBLE)


@pytest.mark.parametrize("case", sorted(BAD_CLAIMS))
def test_broken_claims_row_is_rejected_naming_the_row_and_key(case, tmp_path):
    rows, words = BAD_CLAIMS[case]
    (tmp_path / "zz_broken.yaml").write_text(yaml.safe_dump(rows))
    with pytest.raises(ValueError) as info:
        load_claims(sorted((ROOT / "config" / "claims").glob("*.yaml")) + [tmp_path / "zz_broken.yaml"])
    for word in words:
        assert word in str(info.value), f"{case}: message does not name {word!r}: {info.value}"


PRODUCIBLE = ["results/onedof/friction_mu_vr.csv"]


@pytest.fixture(scope="module")
def pristine(tmp_path_factory):
    return copy_project(tmp_path_factory.mktemp("bad_input_src"))


def _rejected(work, *extra):
    proc = run_snakemake(work, *small_config_args(work, *extra), check=False, timeout=300)
    text = proc.stdout + proc.stderr
    return proc.returncode, text


def _copy(pristine, tmp_path):
    work = tmp_path / "project"
    shutil.copytree(pristine, work)
    return work


@pytest.mark.pipeline
@pytest.mark.parametrize("case", END_TO_END)
def test_broken_config_stops_the_pipeline_before_any_job(case, pristine, tmp_path):
    override, words = CASES[case]
    work = _copy(pristine, tmp_path)
    path = work / "override.yaml"
    path.write_text(yaml.safe_dump(override))
    code, text = _rejected(work, path)
    print(f"\n[{case}] {override}\n" + "\n".join(text.strip().splitlines()[-6:]))
    assert code != 0, text[-3000:]
    for word in words:
        assert word in text, f"{case}: message does not name {word!r}:\n{text[-3000:]}"
    assert not (work / "results").exists(), (
        f"{case}: something was written: {list((work / 'results').rglob('*'))}"
    )


@pytest.mark.pipeline
@pytest.mark.parametrize("case", ["claims_bad_status"])
def test_broken_claims_row_stops_the_pipeline_before_any_job(case, pristine, tmp_path):
    rows, words = BAD_CLAIMS[case]
    work = _copy(pristine, tmp_path)
    (work / "config" / "claims" / "zz_broken.yaml").write_text(yaml.safe_dump(rows))
    code, text = _rejected(work)
    print(f"\n[{case}] {rows}\n" + "\n".join(text.strip().splitlines()[-6:]))
    assert code != 0
    for word in words:
        assert word in text, f"{case}: message does not name {word!r}:\n{text[-3000:]}"
    assert not (work / "results").exists()
