"""Every result comes from the current code and config: a code edit re-runs exactly the jobs that import it
(and their consumers), a revert or a comment re-runs nothing, a moved project or another path to the same
interpreter re-runs nothing, and an input that no rule makes stops the build before any job."""

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml
from bad_inputs import VALUE_ROW

from project_run import copy_project, run_snakemake, shared_small_run, small_config_args, snakemake_command

#: Jobs that run the exact solver themselves (their scripts build solvers through the registry).
RUN_THE_SOLVER = {"simulate_onedof_fig02", "onedof_sweeps", "friction_table"}
#: Jobs that only read datasets: they re-run after a solver edit only as consumers of new inputs.
ONLY_READ = {"claims_table", "render_notebooks", "fe_figures", "claims_check", "report_captions"}


def dry_run_reasons(work, *args, snakemake=None) -> dict[str, set[str]]:
    """Rule -> the reasons its jobs would run, from a dry run."""
    cmd = snakemake_command(work, *small_config_args(work), *args, "--dry-run")
    if snakemake is not None:
        cmd[0] = str(snakemake)
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    out = proc.stdout + proc.stderr
    reasons: dict[str, set[str]] = {}
    for block in re.split(r"\n(?=(?:local)?rule \w+:)", out):
        m = re.match(r"(?:local)?rule (\w+):", block)
        reason = re.search(r"^\s*reason: (.*)$", block, flags=re.M)
        if m and reason and m[1] != "all":
            reasons.setdefault(m[1], set()).add(reason[1].strip())
    return reasons


@pytest.fixture
def built_copy(tmp_path_factory, tmp_path):
    """A copy of the shared small build (results and Snakemake's records included), to edit freely."""
    source = shared_small_run(tmp_path_factory)
    work = tmp_path / "moved" / "project"
    shutil.copytree(source, work, symlinks=True)
    return work


@pytest.mark.pipeline
def test_a_built_project_copied_to_another_folder_schedules_nothing(built_copy):
    assert dry_run_reasons(built_copy) == {}


@pytest.mark.pipeline
def test_another_path_to_the_same_interpreter_schedules_nothing(built_copy):
    here = Path(sys.executable)
    others = [here.with_name(n) for n in ("python3", "python3.11", "python3.12", "python3.13", "python")]
    alias = next(p for p in others if p.exists() and p.name != here.name)  # a venv has python and python3.X
    assert dry_run_reasons(built_copy, snakemake=alias) == {}


@pytest.mark.pipeline
def test_a_solver_edit_reruns_its_importers_and_their_consumers_and_a_revert_nothing(built_copy):
    exact = built_copy / "src" / "stickslip" / "solvers" / "exact.py"
    original = exact.read_text()
    exact.write_text(original.replace('"""', '"""Edited. ', 1))
    reasons = dry_run_reasons(built_copy)
    changed_code = {rule for rule, why in reasons.items() if any("params" in r.lower() for r in why)}
    assert RUN_THE_SOLVER <= changed_code, reasons
    assert not ONLY_READ & changed_code, reasons
    consumers = set(reasons) - changed_code
    assert all(any("input files updated" in r.lower() for r in reasons[rule]) for rule in consumers), reasons
    assert ONLY_READ & set(reasons), "consumers of the new datasets re-run too"

    exact.write_text(original + "\n# a comment line only\n")
    assert dry_run_reasons(built_copy) == {}, "a comment line is no change of the code"
    exact.write_text(original)
    assert dry_run_reasons(built_copy) == {}


@pytest.mark.pipeline
def test_a_config_comment_and_a_rewrite_with_the_same_values_schedule_nothing(built_copy):
    path = built_copy / "config" / "config.yaml"
    path.write_text(path.read_text() + "\n# a comment\n")
    assert dry_run_reasons(built_copy) == {}
    fe = built_copy / "config" / "fe.yaml"
    fe.write_text(yaml.safe_dump(yaml.safe_load(fe.read_text()), sort_keys=False))  # the order is meaningful
    assert dry_run_reasons(built_copy) == {}


@pytest.mark.pipeline
def test_reordered_keys_and_an_unrelated_scene_schedule_nothing(built_copy):
    """A job depends on what its config says, not on the order of its keys (Snakemake compares params by
    their repr) nor on a scene it does not read: before, reordering onedof.defaults.params re-ran 66 of 74
    jobs and a new 1-DOF scene re-ran the inverse study."""
    path = built_copy / "config" / "config.yaml"
    text = path.read_text()
    lines = text.splitlines(keepends=True)
    start = lines.index("    params:\n", lines.index("  defaults:\n")) + 1
    end = next(i for i in range(start, len(lines)) if not lines[i].startswith("      "))
    assert end - start > 5, lines[start:end]
    lines[start:end] = lines[start:end][::-1]
    scenes = lines.index("  scenes:\n") + 1
    lines[scenes:scenes] = ["    unrelated_probe:\n", "      params: {belt_velocity: 0.7}\n"]
    path.write_text("".join(lines))
    fe = built_copy / "config" / "fe.yaml"
    fe_text = fe.read_text()
    assert "  peer: {mesh: [100, 1], tolerance: 0.005}\n" in fe_text
    fe.write_text(
        fe_text.replace(
            "  peer: {mesh: [100, 1], tolerance: 0.005}", "  peer: {tolerance: 0.005, mesh: [100, 1]}"
        )
    )
    assert dry_run_reasons(built_copy) == {}
    # the edit is seen: a changed value of the defaults re-runs the jobs that read it
    path.write_text("".join(lines).replace("      x0: 0.0 ", "      x0: 0.001 ", 1))
    assert "simulate_onedof_fig02" in dry_run_reasons(built_copy)


@pytest.mark.pipeline
def test_a_new_claims_row_reruns_the_claims_table_and_what_reads_it_only(built_copy):
    row = {**VALUE_ROW, "id": "zz_new_row"}  # a complete, valid row of the bad-input matrix
    (built_copy / "config" / "claims" / "zz_new.yaml").write_text(yaml.safe_dump([row]))
    ids = built_copy / "config" / "claims" / "ids.txt"
    ids.write_text(ids.read_text() + "zz_new_row\n")
    reasons = dry_run_reasons(built_copy)
    assert "claims_table" in reasons, reasons
    assert not [r for r in reasons if r.startswith(("simulate_onedof", "onedof_sweeps", "fe_reading"))], (
        reasons
    )


# -- inputs that no rule makes: the build stops before any job --------------------------------------------


@pytest.fixture(scope="module")
def pristine(tmp_path_factory):
    return copy_project(tmp_path_factory.mktemp("provenance_src"))


def _stopped(pristine, tmp_path, edit) -> str:
    work = tmp_path / "project"
    shutil.copytree(pristine, work)
    extra = edit(work)
    proc = run_snakemake(
        work, *small_config_args(work, *([extra] if extra else [])), check=False, timeout=300
    )
    text = proc.stdout + proc.stderr
    assert proc.returncode != 0, text[-3000:]
    assert not (work / "results").exists(), f"something was written: {list((work / 'results').rglob('*'))}"
    return text


def _claims_dataset_typo(work: Path):
    path = work / "config" / "claims" / "section_03_baseline.yaml"
    path.write_text(
        path.read_text().replace(
            "results/onedof/fig02/{reading}/exact.nc", "results/onedof/fig99/{reading}/exact.nc", 1
        )
    )


@pytest.mark.pipeline
def test_a_claims_dataset_typo_stops_the_build_naming_file_claim_and_key(pristine, tmp_path):
    text = _stopped(pristine, tmp_path, _claims_dataset_typo)
    for word in ("section_03_baseline.yaml", "s3_max_displacement", "dataset", "fig99", "no rule writes"):
        assert word in text, text[-3000:]


@pytest.mark.pipeline
def test_a_notebook_input_typo_stops_the_build_naming_the_key(pristine, tmp_path):
    def edit(work):
        path = work / "override.yaml"
        path.write_text(
            yaml.safe_dump(
                {"notebooks": {"section_03_baseline": {"inputs": ["results/onedof/fig04/eq7.nc"]}}}
            )
        )
        return path

    text = _stopped(pristine, tmp_path, edit)
    for word in ("notebooks.section_03_baseline.inputs", "eq7.nc", "no rule writes"):
        assert word in text, text[-3000:]


@pytest.mark.pipeline
def test_a_deleted_claims_file_stops_the_build_naming_the_lost_ids(pristine, tmp_path):
    text = _stopped(
        pristine,
        tmp_path,
        lambda work: (work / "config" / "claims" / "section_06_deceleration.yaml").unlink(),
    )
    assert "pinned but not found" in text and "s6_" in text, text[-3000:]
