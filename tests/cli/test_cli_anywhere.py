"""The command line and the API from any folder, with outputs a script can use and a law of your own.

Each check runs the `stickslip` console command (a subprocess, from an empty folder outside the project) or
the API call the command makes; tolerances, never bit digests, where two computations are compared."""

import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import stickslip
from stickslip import api
from stickslip.cli import DEFINITIONS, main
from stickslip.io.netcdf import read_dataset
from stickslip.model.laws import LAW_KINDS, FrictionLaw
from stickslip.pipeline.config import ConfigError

STICKSLIP = Path(sys.executable).with_name("stickslip")


def cli(*args, cwd):
    """The console command as a user types it, in ``cwd``."""
    return subprocess.run([str(STICKSLIP), *map(str, args)], cwd=cwd, capture_output=True, text=True)


# -- from any folder ---------------------------------------------------------------------------------------


def test_the_project_root_is_the_checkout_the_package_belongs_to_wherever_the_call_runs(
    tmp_path, monkeypatch
):
    monkeypatch.chdir(tmp_path)
    root = api.project_root()
    assert (root / "config" / "config.yaml").is_file() and tmp_path not in root.parents
    with pytest.raises(ConfigError, match=r"root: .* is not a stickslip project folder: it holds no config"):
        api.project_root(tmp_path)


def test_fe_at_a_disc_speed_no_scene_has_runs_from_an_empty_folder(tmp_path):
    """The issue's command: --speed 2 (no configured scene has 2 mm/s) runs the stem's scene at that speed;
    the friction table is computed as rule friction_table computes it when no build has written it."""
    proc = cli(
        "fe",
        "--scene",
        "section9_kinematic",
        "--speed",
        "2",
        "--t-end",
        "0.01",
        "--no-ensemble",
        "-o",
        "s9.nc",
        cwd=tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    ds = read_dataset(tmp_path / "s9.nc")
    assert ds.attrs["title"].endswith("scene section9_kinematic_2mm_s")
    assert json.loads(ds.attrs["scene_disc"])["surface_speed_mm_s"] == 2.0


def test_fe_rpm_names_the_scene_as_the_config_names_its_speeds():
    config = api.load_project_config()
    name, entry = api.fe_scene_name(config["fe"]["scenes"], "section11_penalty", rpm=30.0)
    assert name == "section11_penalty_30rpm"
    assert entry["disc"] == {"speed_rev_per_min": 30.0} and entry["contact"]["method"] == "penalty"
    # a configured speed is that scene, unchanged
    assert api.fe_scene_name(config["fe"]["scenes"], "section11_penalty", speed=0.5) == (
        "section11_penalty_0p5mm_s",
        None,
    )


def test_the_computed_friction_table_is_the_one_rule_friction_table_writes(tmp_path):
    """Same study function, same CSV format: equal to the table the pipeline's script writes."""
    from stickslip.fe.params import FrictionTable
    from stickslip.schema import Onedof
    from stickslip.studies.onedof import friction_table_from_config

    config = api.load_project_config()
    computed = api._fe_friction_table(config, config["fe"]["friction_table"], tmp_path, None)
    ds = friction_table_from_config(Onedof.model_validate(config["onedof"]))
    assert computed.speeds[0] == 0.0 and len(computed.speeds) == ds.sizes["relative_speed"]
    np.testing.assert_allclose(computed.mu, ds.mu.values, rtol=1e-9)
    assert isinstance(computed, FrictionTable)


# -- run: a figure's own claims, outcome first, data a script can read ------------------------------------


def test_run_scene_fig06_json_from_an_empty_folder(tmp_path):
    proc = cli("run", "--scene", "fig06", "--json", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr  # a divergence is the model's answer
    report = json.loads(proc.stdout)  # stdout is the JSON alone: the text goes to stderr
    assert report["status"] == "diverged" and report["outcome"] == "diverged"
    assert "grows without bound" in report["mechanism"]
    metrics = report["metrics"]
    assert [p["value"] for p in metrics["stick_time"]["paper"]] == [4.6]  # Fig. 6's numbers, not Fig. 2's
    assert {p["claim"] for p in metrics["amplitude_peak_to_zero"]["paper"]} == {"s5_fig6_peak_to_zero"}
    assert metrics["stick_time"]["value"] is None  # no steady cycle to measure: null, not NaN
    assert metrics["first_stick_time"]["value"] == pytest.approx(2.9, abs=0.05)  # computed before diverging
    assert all(m["definition"] for m in metrics.values())
    assert proc.stderr.startswith("outcome: diverged: slip damping")


def test_run_csv_file_and_the_printed_block_define_every_metric(tmp_path, capsys):
    out = tmp_path / "m.csv"
    assert main(["run", "--t-end", "20", "--transient", "5", "--csv", str(out)]) == 0
    text = capsys.readouterr().out
    lines = text.splitlines()
    assert lines[0] == "outcome: stick slip: stick-slip cycle"  # the answer first, then the table
    assert lines[3].split() == ["metric", "this", "run", "baseline", "(computed)", "paper", "(claim)"] or (
        lines[3].lstrip().startswith("metric")
    )
    for name, definition in DEFINITIONS.items():
        assert f"    {name}: {definition}" in text
    rows = {r["metric"]: r for r in csv.DictReader(out.open())}
    assert set(rows) == set(DEFINITIONS)
    ptp, ptz = float(rows["amplitude_peak_to_peak"]["value"]), float(rows["amplitude_peak_to_zero"]["value"])
    # the baseline oscillates about an offset centre: peak-to-zero above half the swing, as the footnote says
    assert ptz > ptp / 2 and "never crosses x = 0" in rows["amplitude_peak_to_zero"]["definition"]
    assert rows["frequency_peaks"]["units"] == "Hz" and "s3_frequency" in rows["frequency_peaks"]["claims"]


def test_run_help_defines_every_metric():
    proc = subprocess.run([str(STICKSLIP), "run", "--help"], capture_output=True, text=True)
    assert proc.returncode == 0
    for name in DEFINITIONS:
        assert f"  {name}: " in proc.stdout
    assert "peak-to-zero above half its" in proc.stdout.replace("\n  ", " ").replace("\n", " ")


def test_json_and_csv_cannot_both_go_to_stdout(capsys):
    with pytest.raises(SystemExit) as exit_:
        main(["run", "--json", "--csv"])
    assert exit_.value.code == 2 and "--json/--csv: only one" in capsys.readouterr().err


# -- results like solve_ivp's -------------------------------------------------------------------------------


def test_a_numerical_failure_exits_1_and_says_so_first(capsys):
    """M = 1e300: the exact solver cannot advance (zero-length segments): nothing computed, not an answer."""
    assert main(["run", "--mass", "1e300", "--t-end", "20", "--transient", "5"]) == 1
    first = capsys.readouterr().out.splitlines()[0]
    assert first.startswith("outcome: failed: numerical failure, nothing computed")


def test_every_variable_is_there_whatever_the_outcome():
    ok = stickslip.simulate(t_end=20.0, transient=5.0)
    diverged = stickslip.simulate(mu_s=0.8)
    failed = stickslip.simulate(mass=1e300, t_end=20.0, transient=5.0)
    assert set(ok.data_vars) == set(diverged.data_vars) == set(failed.data_vars)
    assert [d.attrs["status"] for d in (ok, diverged, failed)] == ["success", "diverged", "failed"]
    assert [d.attrs["success"] for d in (ok, diverged, failed)] == [1, 1, 0]
    assert math.isnan(float(failed.stick_time)) and math.isnan(float(diverged.stick_time))
    meanings = ok.outcome.attrs["flag_meanings"].split()
    assert [meanings[int(d.outcome)] for d in (ok, diverged, failed)] == ["stick_slip", "diverged", "failed"]


# -- your own friction law -----------------------------------------------------------------------------------


def test_a_callable_law_solves_as_the_same_built_in_law():
    """mu_s / (1 + delta v) as a lambda and as the built-in rational law: the same switch solver, the same
    motion (to the integrator's tolerance: the two evaluate the formula in different floating-point order)."""
    run = dict(t_end=20.0, transient=5.0)
    own = stickslip.simulate(
        law=lambda v: 0.5 / (1.0 + 0.5 * v), law_derivative=lambda v: -0.25 / (1 + 0.5 * v) ** 2, **run
    )
    built_in = stickslip.simulate(law={"kind": "rational", "delta": 0.5}, **run)
    assert own.attrs["status"] == "success" and own.attrs["method_name"] == "switch"
    assert own.attrs["scene_friction_law"].startswith("CallableLaw(mu=<lambda>, static=0.5")
    np.testing.assert_allclose(own.displacement.values, built_in.displacement.values, atol=1e-6)
    for metric in ("amplitude_peak_to_peak", "frequency_peaks", "stick_time"):
        assert float(own[metric]) == pytest.approx(float(built_in[metric]), rel=1e-6)


def test_two_callables_are_never_taken_for_each_other():
    a = stickslip.simulate(law=lambda v: 0.5 / (1.0 + 0.5 * v), t_end=20.0, transient=5.0)
    b = stickslip.simulate(law=lambda v: 0.5 / (1.0 + 0.2 * v), t_end=20.0, transient=5.0)
    assert a.attrs["scene_friction_law"] != b.attrs["scene_friction_law"]
    assert float(a.amplitude_peak_to_peak) != pytest.approx(float(b.amplitude_peak_to_peak), rel=1e-3)


def test_a_friction_law_subclass_is_solved_too():
    class Halved(FrictionLaw):
        kind = "halved"
        static = 0.5

        def mu_continued(self, speed):
            return (
                0.25 + 0.25 * np.exp(-np.asarray(speed, dtype=float))
                if not isinstance(speed, float)
                else (0.25 + 0.25 * math.exp(-speed))
            )

    ds = stickslip.simulate(law=Halved(), t_end=20.0, transient=5.0)
    assert ds.attrs["method_name"] == "switch" and ds.attrs["status"] in ("success", "diverged")


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"law": lambda v: -0.1}, r"law: the static limit must be finite and > 0"),
        ({"law": lambda v: 0.5 - v}, r"law: mu\([\d.]+ mm/s\) = -0\.\d+; mu must be finite and >= 0"),
        ({"law": lambda v: 0.5 if v == 0 else 0.6}, r"law: mu\(0\+\) = 0\.6 exceeds the static limit 0\.5"),
        ({"law": lambda v: 1 / 0}, r"law: evaluating the law failed: ZeroDivisionError"),
        (
            {"law": lambda v: 0.5, "law_derivative": lambda v: 1.0},
            r"law derivative: dmu\(1e-06 mm/s\) = 1\.0",
        ),
        (
            {"law": lambda v: 0.5, "method": "exact"},
            r"law: a 'callable' friction law is solved by the 'switch'",
        ),
        ({"law": 3}, r"law: expected a config mapping .* or a callable mu\(v_r\), got int"),
    ],
)
def test_a_bad_law_is_refused_before_the_run_naming_the_key(kwargs, message):
    with pytest.raises(ConfigError, match=message):
        stickslip.simulate(**kwargs)


def test_laws_lists_every_kind_with_formula_parameters_and_units(tmp_path):
    proc = cli("laws", "--json", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    kinds = {k["kind"]: k for k in json.loads(proc.stdout)}
    assert set(LAW_KINDS) <= set(kinds)
    assert {p["name"]: p["units"] for p in kinds["stribeck"]["parameters"]} == {
        "mu_s": "1",
        "mu_k": "1",
        "v_s": "mm/s",
    }
    assert "exp(-|v_r| / v_s)" in kinds["stribeck"]["formula"]
    assert {p["name"] for p in kinds["tabulated"]["parameters"]} == {"path", "static_mu"}
    text = cli("laws", cwd=tmp_path).stdout
    assert "    path [file] (required)" in text and "callable (Python only)" in text


def test_the_plot_title_names_the_law_once_and_leaves_the_reading_to_the_figure(tmp_path, monkeypatch):
    import matplotlib.pyplot as plt

    import stickslip.presentation.plots as plots

    seen = {}

    def figure(runs, spec, reading):
        seen.update(spec, reading=reading)
        return plt.figure()

    monkeypatch.setattr(plots, "onedof_figure", figure)
    argv = ["run", "--law", "stribeck", "mu_k=0.3", "v_s=0.5", "--t-end", "20", "--transient", "5"]
    assert main([*argv, "--plot", str(tmp_path / "p.png")]) == 0
    assert seen["title"] == "custom: method switch, friction law StribeckLaw(mu_s=0.5, mu_k=0.3, v_s=0.5)"
    assert seen["reading"] == "consistent_caption" and "consistent_caption" not in seen["title"]


def test_two_tables_in_memory_are_never_taken_for_each_other():
    """A TabulatedLaw built in memory has no source to tell it by: recorded by a digest of its values."""
    from stickslip.model.laws import TabulatedLaw

    run = dict(t_end=20.0, transient=5.0)
    a = stickslip.simulate(law=TabulatedLaw(np.array([0.0, 0.5, 1.0]), np.array([0.5, 0.4, 0.35])), **run)
    b = stickslip.simulate(law=TabulatedLaw(np.array([0.0, 0.5, 1.0]), np.array([0.5, 0.3, 0.25])), **run)
    assert a.attrs["scene_friction_law"] != b.attrs["scene_friction_law"]
    assert float(a.amplitude_peak_to_peak) != pytest.approx(float(b.amplitude_peak_to_peak), rel=1e-3)
