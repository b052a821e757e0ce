"""Bad configuration fails before any job runs, naming the key; nothing is written."""

import pytest
import yaml

from stickslip.io.scenes import run_spec
from stickslip.model import ParameterError

from project_run import copy_project, run_snakemake


@pytest.fixture(scope="module")
def config(repo_root):
    return yaml.safe_load((repo_root / "config" / "config.yaml").read_text())


def test_every_figure_run_resolves(config):
    for fig in config["onedof"]["figures"].values():
        for reading in fig["readings"]:
            for method in fig["methods"]:
                spec = run_spec(config, fig["scene"], reading, method)
                assert spec.t_eval[-1] == pytest.approx(spec.t_end)


@pytest.mark.parametrize(
    "mutate,key",
    [
        (lambda c: c["onedof"]["scenes"]["fig02"]["params"].update(mass=float("nan")), "mass"),
        (lambda c: c["onedof"]["readings"]["consistent_caption"].update(variant="eq5"), "variant"),
        (lambda c: c["onedof"]["methods"]["ode45"].update(rtoll=1e-3), "rtoll"),
        (lambda c: c["onedof"]["methods"]["ode45"].update(solver="euler"), "solver"),
    ],
)
def test_run_spec_errors_name_the_key(config, mutate, key):
    import copy

    bad = copy.deepcopy(config)
    mutate(bad)
    with pytest.raises(ParameterError, match=key):
        for fig in bad["onedof"]["figures"].values():
            for reading in fig["readings"]:
                for method in fig["methods"]:
                    run_spec(bad, fig["scene"], reading, method)


@pytest.mark.pipeline
@pytest.mark.parametrize(
    "patch,needle",
    [
        ({"onedof": {"defaults": {"params": {"stiffness": -5.0}}}}, "stiffness"),
        ({"onedof": {"defaults": {"t_end": "forty"}}}, "t_end"),
        ({"onedof": {"scenes": {"fig02": {"params": {"mass": float("nan")}}}}}, "mass"),
        ({"onedof": {"methods": {"ode45": {"solver": "euler"}}}}, "solver"),
    ],
)
def test_snakemake_rejects_bad_config_before_running(tmp_path, patch, needle):
    work = copy_project(tmp_path)
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(patch))
    proc = run_snakemake(work, "--configfile", str(bad), check=False)
    assert proc.returncode != 0
    assert needle in proc.stdout + proc.stderr
    assert not (work / "results").exists()


def test_a_budgeted_method_records_a_stall_as_a_failed_run(config):
    import copy

    cfg = copy.deepcopy(config)
    cfg["onedof"]["methods"]["ode45"]["budget"] = {"max_rhs": 500}
    spec = run_spec(cfg, "fig02", "consistent_caption", "ode45")
    traj = spec.solver().solve(spec.model, spec.t_end, spec.t_eval)
    assert not traj.ok and "budget" in traj.stats.message
    cfg["onedof"]["methods"]["ode45"]["budget"] = {"max_rhs": 0}
    with pytest.raises(ParameterError, match="onedof.methods.ode45.budget"):
        run_spec(cfg, "fig02", "consistent_caption", "ode45")
