"""Stale results are impossible: a job declares the config it reads (``params:``), so editing a value re-runs
exactly the jobs that read it (Snakemake's params trigger) - and nothing else."""

import re

import pytest
import yaml

from project_run import run_snakemake, shared_small_run, small_config_args


def jobs_to_run(work, *args) -> dict[str, int]:
    """Rule -> job count of a dry run (the 'Job stats' table)."""
    out = run_snakemake(work, *args, "--dry-run").stdout
    table = out.split("Job stats:")[-1] if "Job stats:" in out else ""
    return {m[1]: int(m[2]) for m in re.finditer(r"^(\w+)\s+(\d+)\s*$", table, flags=re.M) if m[1] != "total"}


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    work = shared_small_run(tmp_path_factory)
    return work, small_config_args(work)


def override(tmp_path, data) -> str:
    path = tmp_path / "override.yaml"
    path.write_text(yaml.safe_dump(data))
    return str(path)


@pytest.mark.pipeline
def test_nothing_to_do_without_an_edit(small_run):
    work, args = small_run
    assert jobs_to_run(work, *args) == {}


@pytest.mark.pipeline
def test_editing_an_fe_material_value_reruns_the_fe_jobs_and_no_1dof_job(small_run, tmp_path):
    work, args = small_run
    jobs = jobs_to_run(
        work, *args, override(tmp_path, {"fe": {"defaults": {"beam": {"density_kg_m3": 7800.0}}}})
    )
    assert any(rule.startswith("fe_reading") for rule in jobs), jobs
    assert not [
        rule for rule in jobs if rule.startswith(("simulate_onedof", "onedof_sweeps", "critical_speed"))
    ]


@pytest.mark.pipeline
def test_editing_one_scene_reruns_that_scene_only(small_run, tmp_path):
    work, args = small_run
    edit = {"onedof": {"scenes": {"fig07": {"params": {"damping": 0.11}}}}}
    jobs = jobs_to_run(work, *args, override(tmp_path, edit))
    assert jobs.get("simulate_onedof_fig07") == 1, jobs
    assert "simulate_onedof_fig02" not in jobs and "onedof_sweeps" not in jobs, jobs
    assert not [rule for rule in jobs if rule.startswith(("fe_", "critical_speed", "eq6", "dense_map"))], jobs


@pytest.mark.pipeline
def test_editing_the_ensemble_reruns_the_claimed_datasets(small_run, tmp_path):
    work, args = small_run
    jobs = jobs_to_run(work, *args, override(tmp_path, {"ensemble": {"seeds": [3, 4]}}))
    assert "simulate_onedof_fig02" in jobs and "onedof_sweeps" in jobs and "claims_table" in jobs, jobs


FE_JOBS = ("fe_reading", "fe_studies", "fe_setup_fit", "fe_model_comparison")


@pytest.mark.pipeline
@pytest.mark.parametrize(
    "edit,expected",
    [
        # read by the 4 control readings only (the first reading runs the scenes' own window)
        ({"control_readings_t_end": 0.003}, {"fe_reading": 4}),
        # read by no job of the pipeline
        ({"reduced": {"safety_factor": 0.4}}, {}),
        ({"sweeps": {"angle_sweep": {"t_end": 0.003}}}, {"fe_studies": 1}),
        ({"stability": {"slopes": [-0.2, 0.0]}}, {"fe_studies": 1}),
        ({"comparison": {"t_end": 0.003}}, {"fe_model_comparison": 1}),
        # a scene no study starts from: every reading's job and the model comparison read it
        (
            {"scenes": {"section10_fixed_normal_15p2rpm": {"disc": {"speed_rev_per_min": 15.0}}}},
            {"fe_reading": 5, "fe_model_comparison": 1},
        ),
        # the defaults: every FE job
        (
            {"defaults": {"solver": {"stiffness_damping": 4.0e-9}}},
            {"fe_reading": 5, "fe_studies": 1, "fe_setup_fit": 2, "fe_model_comparison": 1},
        ),
    ],
    ids=["control_readings_t_end", "reduced", "sweeps", "stability", "comparison", "scenes", "defaults"],
)
def test_an_fe_key_reruns_exactly_the_fe_jobs_that_read_it(small_run, tmp_path, edit, expected):
    work, args = small_run
    jobs = jobs_to_run(work, *args, override(tmp_path, {"fe": edit}))
    assert {rule: n for rule, n in jobs.items() if rule in FE_JOBS} == expected, jobs
    assert not [rule for rule in jobs if rule.startswith(("simulate_onedof", "onedof_sweeps", "critical"))]
