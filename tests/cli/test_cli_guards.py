"""Commands that cannot be misused: the CLI and the API never write into the pipeline's results, refuse an
output they cannot write and a run above the pipeline's cost guard, all before any work, each with a message
naming the option (or API key), never a traceback."""

import re

import numpy as np
import pytest
import xarray as xr

import stickslip
from stickslip import api
from stickslip.cli import main
from stickslip.pipeline.config import ConfigError
from stickslip.schema import MAX_ENSEMBLE_SEEDS, MAX_SAMPLES_PER_RUN

from project_run import ROOT

CATALOGUED = "results/onedof/fig02/consistent_caption/exact.nc"


@pytest.fixture
def no_work(monkeypatch):
    """Every computation the commands can start fails the test if it is reached."""

    def forbidden(*args, **kwargs):
        raise AssertionError("work started before the input was checked")

    import stickslip.studies.fe_scene
    import stickslip.studies.onedof

    monkeypatch.setattr(stickslip.studies.onedof, "scene_run_dataset", forbidden)
    monkeypatch.setattr(stickslip.studies.onedof, "friction_table_from_config", forbidden)
    monkeypatch.setattr(stickslip.studies.fe_scene, "scene_dataset", forbidden)


def refused(argv, capsys) -> str:
    with pytest.raises(SystemExit) as exit_:
        main(argv)
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err
    return err


@pytest.fixture
def project(tmp_path):
    """A second checkout of the project (its config), whose results folder is the build's."""
    (tmp_path / "proj").mkdir()
    (tmp_path / "proj" / "config").symlink_to(ROOT / "config")
    (tmp_path / "proj" / "results").mkdir()
    return tmp_path / "proj"


# -- outputs -------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("force", [[], ["--force"]])
def test_a_catalogue_path_is_refused_even_with_force(project, force, no_work, capsys):
    err = refused(["run", "--mu-s", "0.6", "-o", str(project / CATALOGUED), *force], capsys)
    assert "-o/--output:" in err and "inside the pipeline's results folder" in err
    assert "a catalogue path" in err and "--force does not change this" in err
    assert not (project / CATALOGUED).exists()


def test_anything_under_the_results_folder_is_refused_from_the_cli_and_the_api(
    project, no_work, monkeypatch, capsys
):
    monkeypatch.chdir(project)
    err = refused(["fe", "--scene", "section9_kinematic", "--speed", "2", "-o", "results/mine.nc"], capsys)
    assert "-o/--output: 'results/mine.nc' is inside the pipeline's results folder" in err
    with pytest.raises(ConfigError, match=r"output: .* is inside the pipeline's results folder"):
        stickslip.simulate(output=project / "results" / "sub" / "x.nc", root=project)
    with pytest.raises(ConfigError, match=r"plot: .* is inside the pipeline's results folder"):
        api.check_output(project / "results" / "x.png", key="plot")


@pytest.mark.parametrize(
    "target, message",
    [
        ("{tmp}", r"is a directory; name a file"),
        ("/proc/x.nc", r"'/proc/x\.nc' cannot be written"),
        ("{tmp}/plain.txt/x.nc", r"cannot be written: .*plain\.txt' is not a directory"),
        ("{tmp}/exists.nc", r"exists; pass --force"),
    ],
)
def test_an_output_that_cannot_be_written_is_refused_before_any_work(
    tmp_path, target, message, no_work, capsys
):
    (tmp_path / "plain.txt").write_text("x")
    (tmp_path / "exists.nc").write_text("x")
    target = target.format(tmp=tmp_path)
    assert re.search(r"-o/--output: .*" + message, refused(["run", "-o", target], capsys))
    assert re.search(r"--plot: .*" + message, refused(["run", "--plot", target], capsys))
    assert re.search(r"--json: .*" + message, refused(["run", "--json", target], capsys))


def test_force_overwrites_a_file_of_yours(tmp_path, capsys):
    out = tmp_path / "m.json"
    out.write_text("old")
    assert main(["run", "--t-end", "20", "--transient", "5", "--json", str(out), "--force"]) == 0
    assert out.read_text().startswith("{")


# -- the pipeline's cost guard -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "argv, option, cost",
    [
        (["run", "--t-end", "1e9"], "--t-end", "1e+11 samples per run"),
        (["run", "--output-dt", "1e-9"], "--output-dt", "4e+10 samples per run"),
        (
            ["fe", "--scene", "section9_kinematic", "--speed", "0.5", "--t-end", "1e9"],
            "--t-end",
            "4e+14 samples",
        ),
    ],
)
def test_a_run_above_the_cost_guard_is_refused_naming_option_cost_and_bound(
    argv, option, cost, no_work, capsys
):
    err = refused(argv, capsys).splitlines()[-1]  # fe says first, on stderr, what it is about to run
    assert err.startswith(f"stickslip {argv[0]}: error: {option}")
    assert cost in err and f"more than the limit {MAX_SAMPLES_PER_RUN:.3g}" in err


@pytest.mark.parametrize(
    "argv",
    [["run", "--ensemble"], ["fe", "--scene", "section9_kinematic", "--speed", "0.5", "--t-end", "0.01"]],
)
def test_an_ensemble_of_too_many_seeds_is_refused_before_any_work(tmp_path, argv, no_work, capsys):
    overlay = tmp_path / "seeds.yaml"
    overlay.write_text(f"ensemble:\n  seeds: {list(range(100_000))}\n")
    err = refused([*argv, "--configfile", str(overlay)], capsys)
    assert "--ensemble (ensemble.seeds): 100000 seeds make 100003 runs" in err
    assert f"more than the limit {MAX_ENSEMBLE_SEEDS} seeds" in err


def test_allow_expensive_lets_the_user_take_the_cost(tmp_path):
    """As in the pipeline: the guard is a question, `allow_expensive: true` (a config file's) the answer."""
    from dataclasses import replace

    from stickslip.studies.specs import baseline_spec

    overlay = tmp_path / "expensive.yaml"
    overlay.write_text("allow_expensive: true\n")
    project = api.onedof_project(api.load_project_config([overlay]))
    costly = replace(baseline_spec(project.onedof), t_end=1e9)
    with pytest.raises(ConfigError, match="samples per run, more than the limit"):
        api.check_run_cost(costly)
    api.check_run_cost(costly, allow_expensive=project.allow_expensive)  # the same run, taken on purpose


# -- not a dataset, a missing root ---------------------------------------------------------------------------


def test_show_exits_non_zero_on_a_file_that_is_not_a_dataset(tmp_path, capsys):
    err = refused(["show", "/etc/passwd"], capsys)
    assert "FILE: /etc/passwd: not a netCDF dataset" in err and "make repair" not in err
    refused(["show", str(tmp_path / "missing.nc")], capsys)
    xr.Dataset({"a": ("x", np.arange(3.0))}).to_netcdf(
        tmp_path / "foreign.nc"
    )  # netCDF, not ours: no checksum
    assert main(["show", str(tmp_path / "foreign.nc")]) == 1
    assert "checksum: MISMATCH" in capsys.readouterr().out


def test_a_missing_root_is_a_message_not_a_key_error(tmp_path, capsys):
    for argv in (["run"], ["claims", "--figure", "2"], ["fe", "--scene", "x"], ["show", "results/x.nc"]):
        err = refused([*argv, "--root", str(tmp_path / "nowhere")], capsys)
        assert "--root: " in err and "is not a stickslip project folder: it does not exist" in err


def test_a_truncated_dataset_is_a_failed_check_and_a_foreign_file_is_not_a_dataset(tmp_path, capsys):
    """A netCDF file cut short (a killed copy) is a damaged dataset: summarised as far as it goes, exit 1,
    `make repair` advised; a file that is no netCDF at all is bad input (exit 2), with no rebuild advice."""
    import stickslip
    from stickslip.io.netcdf import write_dataset

    path = tmp_path / "run.nc"
    write_dataset(stickslip.simulate(t_end=20.0, transient=5.0), path, scene={}, interpretation="", method={})
    path.write_bytes(path.read_bytes()[:400])
    assert main(["show", str(path)]) == 1
    assert "checksum: MISMATCH" in capsys.readouterr().out
    (tmp_path / "notes.nc").write_text("not a dataset\n")
    err = refused(["show", str(tmp_path / "notes.nc")], capsys)
    assert "not a netCDF dataset" in err and "make repair" not in err


def test_show_says_the_outcome_first_and_why_each_value_is_missing(tmp_path, capsys):
    from stickslip.io.netcdf import write_dataset

    path = tmp_path / "fig06.nc"
    write_dataset(stickslip.simulate(scene="fig06"), path, scene={}, interpretation="", method={})
    assert main(["show", str(path)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[1].startswith("  outcome: diverged: slip damping C - mu_s N sigma = 1.5 - 4 = -2.5")
    missing = [ln for ln in lines if ln.startswith("  n/a (")]
    assert (
        len(missing) == 1
        and "n/a (not defined by this run, whose outcome is diverged): stick_time" in missing[0]
    )
    assert not any(ln.endswith("= n/a") for ln in lines)  # no value printed undefined without its reason
