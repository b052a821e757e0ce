"""Broken inputs stop the real pipeline at parse time: the message names the key, and nothing is written
(a few cases of each kind of the matrix in tests/bad_inputs.py)."""

import shutil

import pytest
import yaml
from bad_inputs import BAD_CLAIMS, BAD_CLAIMS_IN_CONTEXT, BAD_FILES, CASES, END_TO_END

from project_run import copy_project, run_snakemake, small_config_args


def test_the_matrix_covers_every_class_with_at_least_eighty_inputs():
    total = len(CASES) + len(BAD_FILES) + len(BAD_CLAIMS) + len(BAD_CLAIMS_IN_CONTEXT)
    assert total >= 80, total


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
    assert f"{path}:" in text, f"{case}: message does not name the file and line of the key:\n{text[-3000:]}"
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
