"""Your own scenario in one command: the `stickslip` console command and `stickslip.simulate`/`simulate_fe`.

The datasets they write are the pipeline's (same study function, same writer): compared with the shared small
build variable by variable (``stickslip.io.compare``: data bit for bit on the same machine and code path,
CPU times and attributes such as ``history`` excluded)."""

import subprocess
import sys

import numpy as np
import pytest

import stickslip
from stickslip.cli import main
from stickslip.io.compare import data_differences
from stickslip.io.netcdf import read_dataset, write_dataset
from stickslip.model.equations import BeltModel
from stickslip.model.laws import AffineLaw, LawModel, StribeckLaw
from stickslip.model.params import BeltParams, ParameterError
from stickslip.pipeline.config import ConfigError
from stickslip.solvers import make_solver

from project_run import ROOT, shared_small_run

BASE = BeltParams(
    mass=1.0, stiffness=5.0, damping=1.5, mu_s=0.5, sigma=0.5, normal_force=10.0, v0=0.5, belt_velocity=0.5
)


def small_configs(root):
    return sorted((root / "config" / "test").glob("*.yaml"))


# -- solvers and config: any law in a scene ----------------------------------------------------------------


@pytest.mark.parametrize("solver", ["exact", "sign_rk", "smooth", "karnopp", "moreau"])
def test_a_readings_solver_given_a_stribeck_law_names_the_switch_solver(solver):
    with pytest.raises(ParameterError, match=r"'stribeck' friction law needs the 'switch' solver"):
        make_solver(solver).solve(LawModel(BASE, StribeckLaw(0.5, 0.3, 0.5)), 5.0, np.linspace(0, 5, 11))


def test_the_exact_solver_takes_an_affine_law_as_its_consistent_reading():
    t = np.linspace(0.0, 20.0, 201)
    via_law = make_solver("exact").solve(LawModel(BASE, AffineLaw(0.5, 0.5)), 20.0, t)
    reading = make_solver("exact").solve(BeltModel.build(BASE, "consistent"), 20.0, t)
    assert np.array_equal(via_law.x, reading.x) and np.array_equal(via_law.phase, reading.phase)


def test_a_scene_law_under_a_figure_with_the_exact_method_is_a_config_error_naming_the_figure(tmp_path):
    overlay = tmp_path / "law.yaml"
    overlay.write_text(
        "onedof:\n  scenes:\n    fig02:\n      law: {kind: stribeck, mu_s: 0.5, mu_k: 0.3, v_s: 0.5}\n"
    )
    with pytest.raises(ConfigError, match=r"onedof\.figures\.fig02\.method: a friction law needs .*'switch'"):
        stickslip.simulate(configfiles=[overlay])


def test_a_scene_law_runs_under_the_switch_solver_and_is_recorded():
    ds = stickslip.simulate(
        law={"kind": "coulomb", "mu_k": 0.4}, t_end=12.0, transient=4.0, count_window=12.0
    )
    assert ds.attrs["method_name"] == "switch"
    assert ds.attrs["scene_friction_law"] == "CoulombLaw(mu_s=0.5, mu_k=0.4)"
    assert int(ds.solver_status) == 0
    # the stick phase moves with the belt whatever the law
    assert float(ds.stick_velocity) == pytest.approx(0.5, rel=1e-9)


def test_your_runs_ensemble_perturbs_what_the_pipelines_job_for_it_perturbs():
    """Only the run's own reading and method, as rule simulate_onedof's job: the exact solver has no step to
    change, so its ensemble has no step member (it would repeat the base run); ode45's has one."""
    from stickslip.ensemble import MEMBER_DIM

    def labels(method):
        ds = stickslip.simulate(method=method, t_end=12.0, transient=4.0, count_window=12.0, ensemble=True)
        return list(ds[f"{MEMBER_DIM}_label"].values)

    assert labels("exact") == ["base", "perturbed-1", "perturbed-2", "window"]
    assert labels("ode45") == ["base", "perturbed-1", "perturbed-2", "step", "window"]


# -- the command line: options checked as config keys -----------------------------------------------------


@pytest.mark.parametrize(
    "argv, message",
    [
        (
            ["run", "--mu-s", "-1"],
            r"--mu-s \(onedof\.scenes\.custom\.params\.mu_s\): Input should be greater than 0",
        ),
        (["run", "--damping", "nan"], r"--damping \(onedof\.scenes\.custom\.params\.damping\)"),
        (
            ["run", "--law", "stribeck", "mu_k=0.3", "v_s=0.5", "--method", "exact"],
            r"--law/--method .*'switch'",
        ),
        (
            ["run", "--law", "stribeck", "mu_k=0.3", "bogus=1"],
            r"--law \(onedof\.scenes\.custom\.law\.bogus\)",
        ),
        (["run", "--law", "stribeck", "mu_k"], r"--law: expected KEY=VALUE"),
        (["run", "--reading", "nope"], r"--reading: 'nope' is not an entry of onedof\.readings"),
        (
            ["run", "--t-end", "5", "--transient", "6"],
            r"--transient \(onedof\.scenes\.custom\.transient\): 6\.0 does not fit",
        ),
        (
            ["fe", "--scene", "section99_nothing", "--speed", "0.7"],
            r"--scene: fe\.scenes\.section99_nothing: no such scene",
        ),
        (["fe", "--scene", "section9_kinematic"], r"--scene: .*a stem, not a scene: add --speed"),
        (["fe", "--scene", "section9_kinematic", "--speed", "nan"], r"--speed: .* number > 0, got nan"),
        (["fe", "--scene", "section9_kinematic", "--rpm", "-3"], r"--rpm: .* finite number > 0, got -3"),
        (["fe", "--scene", "section9_kinematic", "--speed", "1", "--rpm", "3"], r"--speed: .*not both"),
        (["fe", "--scene", "section9_kinematic", "--speed", "1", "--t-end", "inf"], r"--t-end: .*got inf"),
        (["run", "--root", "/nonexistent/stickslip"], r"--root: '/nonexistent/stickslip' is not a stickslip"),
        (["run", "--configfile", "/nonexistent/x.yaml"], r"/nonexistent/x\.yaml: cannot read"),
    ],
)
def test_a_bad_option_is_an_error_naming_the_option(argv, message, capsys):
    with pytest.raises(SystemExit) as exit_:
        main(argv)
    assert exit_.value.code == 2
    assert __import__("re").search(message, capsys.readouterr().err)


def test_an_unknown_option_is_refused_by_name(capsys):
    with pytest.raises(SystemExit):
        main(["run", "--mu-k", "0.3"])
    assert "unrecognized arguments: --mu-k" in capsys.readouterr().err


def test_every_subcommand_has_help():
    for command in ("run", "fe", "claims", "show"):
        out = subprocess.run(
            [sys.executable, "-m", "stickslip.cli", command, "--help"], capture_output=True, text=True
        )
        assert out.returncode == 0 and f"usage: stickslip {command}" in out.stdout


def test_run_prints_the_metrics_beside_the_baseline_and_the_papers_values(capsys):
    assert main(["run", "--mu-s", "0.6", "--damping", "1.0"]) == 0
    out = capsys.readouterr().out
    for metric in ("amplitude_peak_to_peak", "frequency_peaks", "stick_time", "slip_time"):
        assert metric in out
    # the paper's Section 3 numbers for the baseline, with the claim that quotes each
    assert "0.25 Hz (s3_frequency)" in out and "2.4 s (s3_stick_time)" in out
    assert "scene fig02 with damping=1.0, mu_s=0.6" in out


def test_a_diverging_run_prints_its_mechanism_first_and_is_an_answer_not_an_error(capsys):
    """mu_s = 0.8 under the baseline's reading: slip damping C - mu_s N sigma = 1.5 - 4 < 0, the motion
    grows. As solve_ivp reports, the dataset says so (status, message) and the command exits 0."""
    from stickslip import api

    assert main(["run", "--mu-s", "0.8"]) == 0
    first = capsys.readouterr().out.splitlines()[0]
    assert main(["run", "--scene", "fig06"]) == 0  # the figure's own numbers, not the baseline's
    assert "4.6 s (s5_fig6_stick_time)" in capsys.readouterr().out
    assert first.startswith("outcome: diverged: slip damping") and "1.5 - 4 = -2.5" in first
    ds = api.simulate(mu_s=0.8)
    assert ds.attrs["status"] == "diverged" and ds.attrs["success"] == 1
    assert "grows without bound" in ds.attrs["message"]
    assert "stick_time" in ds and float(ds.first_stick_time) > 0  # every metric there, NaN where undefined


def test_claims_without_a_build_says_how_to_build_it(tmp_path, capsys):
    (tmp_path / "config").symlink_to(ROOT / "config")  # a project, never built
    with pytest.raises(SystemExit):
        main(["claims", "--figure", "2", "--root", str(tmp_path)])
    assert "results/claims/deviations.csv" in capsys.readouterr().err


def test_claims_with_a_misspelt_claims_key_names_file_and_key_without_a_traceback(tmp_path, capsys):
    import shutil

    shutil.copytree(ROOT / "config", tmp_path / "config")
    table = tmp_path / "results" / "claims" / "deviations.csv"
    table.parent.mkdir(parents=True)
    table.write_text("claim,reading,status\n")
    claims = tmp_path / "config" / "claims" / "section_03_baseline.yaml"
    claims.write_text(claims.read_text().replace("tolerance:", "tolerence:", 1))
    with pytest.raises(SystemExit) as exit_:
        main(["claims", "--figure", "2", "--root", str(tmp_path)])
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert "stickslip claims: error:" in err and "section_03_baseline.yaml" in err and "tolerence" in err


def test_show_reports_the_checksum_state_of_a_dataset(tmp_path, capsys):
    ds = stickslip.simulate(t_end=12.0, transient=4.0, count_window=12.0)
    path = tmp_path / "run.nc"
    write_dataset(ds, path, scene={}, interpretation="", method={})
    assert main(["show", str(path)]) == 0
    assert "checksum: ok" in capsys.readouterr().out
    ds2 = read_dataset(path)
    ds2["solver_steps"] = ds2.solver_steps + 1  # the file edited by another program: data no longer sealed
    ds2.to_netcdf(tmp_path / "edited.nc")
    assert main(["show", str(tmp_path / "edited.nc")]) == 1  # summarised as stored, and a failed check
    assert "checksum: MISMATCH" in capsys.readouterr().out


# -- equal to the pipeline's datasets ----------------------------------------------------------------------


@pytest.mark.pipeline
def test_run_output_equals_the_pipelines_dataset_of_the_same_scene(tmp_path_factory, tmp_path):
    work = shared_small_run(tmp_path_factory)
    out = tmp_path / "run.nc"
    argv = ["run", "--scene", "fig02", "--reading", "eq3_text", "--method", "ode45", "-o", str(out)]
    argv += ["--root", str(work), *sum((["--configfile", str(p)] for p in small_configs(work)), [])]
    assert main(argv) == 0
    pipeline = work / "results" / "onedof" / "fig02" / "eq3_text" / "ode45.nc"
    assert data_differences(out, pipeline) == []
    assert read_dataset(out).attrs["title"] == read_dataset(pipeline).attrs["title"]


@pytest.mark.pipeline
def test_fe_output_equals_the_pipelines_scene_dataset(tmp_path_factory, tmp_path):
    work = shared_small_run(tmp_path_factory)
    out = tmp_path / "s9.nc"
    ds = stickslip.simulate_fe(
        "section9_kinematic",
        speed=0.5,
        reading="lower_face_drop",
        output=out,
        configfiles=small_configs(work),
        root=work,
    )
    assert "ensemble_member" in ds.dims  # the ensemble and the step-halving check, as rule fe_reading
    pipeline = work / "results" / "fe" / "lower_face_drop" / "section9_kinematic_0p5mm_s.nc"
    assert data_differences(out, pipeline) == []


def test_claims_prints_the_figures_verdict_and_each_claims_reason(tmp_path, capsys):
    """Two claims on Fig. 2 (one reproduced, one deviating) in the primary reading: 'partly, 1 of 2'; a row
    that holds by construction is listed and not counted."""
    import csv

    from stickslip.claims.table import FIELDS

    (tmp_path / "config").symlink_to(ROOT / "config")
    table = tmp_path / "results" / "claims" / "deviations.csv"
    table.parent.mkdir(parents=True)
    rows = [
        {
            "claim": "s3_frequency",
            "reading": "consistent_caption",
            "status": "deviates",
            "reported": "0.25",
            "measured": "0.27881234567",
            "reason": "0.28 Hz",
            "evidence": "evidence",
        },
        {
            "claim": "s3_max_displacement",
            "reading": "consistent_caption",
            "status": "reproduced",
            "reason": "",
            "evidence": "evidence",
        },
        {
            "claim": "s3_stick_velocity",
            "reading": "consistent_caption",
            "status": "reproduced",
            "reason": "",
            "evidence": "by_construction",
        },
        {
            "claim": "s6_something_else",
            "reading": "consistent_caption",
            "status": "deviates",
            "reason": "x",
            "evidence": "evidence",
        },
    ]
    with open(table, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=FIELDS, restval="")
        writer.writeheader()
        writer.writerows(rows)
    assert main(["claims", "--figure", "2", "--root", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert out.startswith(
        "Fig. 2: partly, 1 of 2 decided claims reproduced in the primary reading consistent_caption"
    )
    assert "- s3_stick_velocity: reproduced  [by construction: not counted]" in out
    assert "- s3_frequency: deviates" in out and "reason: 0.28 Hz" in out
    assert "reported 0.25, measured 0.2788\n" in out  # the table's 0.27881234567, to 4 significant digits
    assert "s6_something_else" not in out  # not a claim about Fig. 2
    # then where Fig. 2 comes from: its runs and image, each with the rule that makes it (the catalogue)
    assert "  results/onedof/fig02/consistent_caption/exact.nc  (rule simulate_onedof_fig02)" in out
    assert "  results/figures/fig02/consistent_caption.png  (rule onedof_figure_fig02)" in out
    assert "results/onedof/fig05/" not in out


def test_fe_runs_from_a_folder_outside_the_project(tmp_path, monkeypatch):
    """The documented command from another folder, with the ensemble and the step-halving check: the project's
    paths (the inverse study's claims glob among them, and the friction table, computed when no build has
    written it) resolve against the project the package belongs to, not the working directory."""
    monkeypatch.chdir(tmp_path)
    args = ["fe", "--scene", "section9_kinematic", "--speed", "0.5", "--t-end", "0.01", "-o", "s9.nc"]
    assert main(args) == 0
    assert "ensemble_member" in read_dataset(tmp_path / "s9.nc").dims
