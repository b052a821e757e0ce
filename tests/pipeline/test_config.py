"""The config as the build resolves it: every figure run resolves, the check reuses the claims rows the parse
has read, a budget stall is a failed run, a null removes an entry (bad values: test_config_errors.py)."""

from pathlib import Path

import pytest
import yaml

from stickslip.model import ParameterError
from stickslip.schema import Onedof
from stickslip.studies.specs import figure_runs, run_spec


@pytest.fixture(scope="module")
def config(repo_root):
    return yaml.safe_load((repo_root / "config" / "config.yaml").read_text())


def test_every_figure_run_resolves(config):
    onedof = Onedof.model_validate(config["onedof"])
    for fig in onedof.figures.values():
        for scene, reading, method in figure_runs(fig):
            spec = run_spec(onedof, scene, reading, method)
            assert spec.t_eval[-1] == pytest.approx(spec.t_end)


def _no_claims_file_read(monkeypatch):
    """Make reading a claims file an error (the claims loader imports load_yaml when it reads)."""

    def refuse(path):
        raise AssertionError(f"{path} was read again")

    monkeypatch.setattr("stickslip.io.yaml_files.load_yaml", refuse)


def test_the_config_check_reads_no_claims_file_the_parse_has_read(repo_root, monkeypatch):
    """The Snakefile reads the claims files once (workflow/rules/common.smk) and hands the rows to the
    config check; a fitted claim id that no row has is the same error as when the check reads the files."""
    from glob import glob

    from stickslip.claims.load import load_claims
    from stickslip.pipeline.config import ConfigError, load_config, validate_config

    monkeypatch.chdir(repo_root)  # inverse.claims_glob, like the parse's claims files, is project-relative
    config = load_config(sorted(glob("config/*.yaml")))
    claims = load_claims(sorted(glob("config/claims/*.yaml")))
    _no_claims_file_read(monkeypatch)
    validate_config(config, producible=["results/onedof/friction_mu_vr.csv"], claims=claims)
    config["inverse"]["figures"]["fig02"]["claims"].append("no_such_claim")
    message = "inverse.figures.fig02.claims: 'no_such_claim' is not a claim id"
    with pytest.raises(ConfigError, match=message):
        validate_config(config, producible=["results/onedof/friction_mu_vr.csv"], claims=claims)
    monkeypatch.undo()
    monkeypatch.chdir(repo_root)
    with pytest.raises(ConfigError, match=message):
        validate_config(config, producible=["results/onedof/friction_mu_vr.csv"])


def test_rows_of_files_outside_the_inverse_glob_are_not_its_claims(repo_root, monkeypatch):
    """Rows of only some of the glob's files: the check reads the glob's files itself (so a fitted claim of a
    file the rows did not come from is still found), and counts no row of a file outside the glob."""
    from glob import glob

    from stickslip.claims.load import load_claims
    from stickslip.pipeline.config import ConfigError, load_config, validate_config

    monkeypatch.chdir(repo_root)
    config = load_config(sorted(glob("config/*.yaml")))
    fitted = config["inverse"]["figures"]["fig02"]["claims"][0]
    without = [f for f in sorted(glob("config/claims/*.yaml")) if fitted not in Path(f).read_text()]
    validate_config(config, producible=["results/onedof/friction_mu_vr.csv"], claims=load_claims(without))
    config["inverse"]["claims_glob"] = "config/claims/sections_09_12.yaml"  # no 1-DOF claim in it
    with pytest.raises(ConfigError, match=f"'{fitted}' is not a claim id"):
        validate_config(
            config,
            producible=["results/onedof/friction_mu_vr.csv"],
            claims=load_claims(sorted(glob("config/claims/*.yaml"))),
        )


def test_a_budgeted_method_records_a_stall_as_a_failed_run(config):
    import copy

    cfg = copy.deepcopy(config)
    cfg["onedof"]["methods"]["ode45"]["budget"] = {"max_rhs": 500}
    spec = run_spec(Onedof.model_validate(cfg["onedof"]), "fig02", "consistent_caption", "ode45")
    traj = spec.solver().solve(spec.model, spec.t_end, spec.t_eval)
    assert not traj.ok and "budget" in traj.stats.message
    cfg["onedof"]["methods"]["ode45"]["budget"] = {"max_rhs": 0}
    with pytest.raises(ParameterError, match="onedof.methods.ode45.budget"):
        run_spec(Onedof.model_validate(cfg["onedof"]), "fig02", "consistent_caption", "ode45")


def test_a_null_in_an_override_file_removes_the_entry(tmp_path, repo_root):
    """Merging can only add or replace: a null value is how the small config drops a figure of the main one
    (and with it the figure's rule); every other entry of the section stays."""
    from stickslip.pipeline.config import load_config

    override = tmp_path / "drop.yaml"
    override.write_text("onedof:\n  figures:\n    fig05: null\n")
    files = sorted((repo_root / "config").glob("*.yaml"))
    main, dropped = load_config(files), load_config([*files, override])
    assert "fig05" in main["onedof"]["figures"] and "fig05" not in dropped["onedof"]["figures"]
    assert set(main["onedof"]["figures"]) - set(dropped["onedof"]["figures"]) == {"fig05"}
