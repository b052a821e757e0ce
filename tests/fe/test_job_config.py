"""Each FE job's params are the resolved part of the fe config it reads (studies.fe_config.job_config):
the order of keys in a file, and keys the job does not read, leave them unchanged (so Snakemake re-runs
nothing); the job reads them back as a typed ``FeJob``."""

import json

import pytest

from stickslip.pipeline.config import load_config
from stickslip.schema import PipelineConfig
from stickslip.schema.fe import FeJob
from stickslip.studies.fe_config import as_mapping, effective_fe, job_config, scene_mapping


def _config(repo_root) -> dict:
    return load_config(sorted((repo_root / "config").glob("*.yaml")))


def _fe(config: dict):
    return effective_fe(PipelineConfig.model_validate(config))


def _reversed(node, reverse=True):
    """Every mapping's keys in the opposite order, except the order of the FE readings themselves (the first
    one is the default reading: that order means something)."""
    if not isinstance(node, dict):
        return node
    items = [(k, _reversed(v, reverse=k != "readings")) for k, v in node.items()]
    return dict(reversed(items) if reverse else items)


def _params(fe, **kw):
    return json.dumps(job_config(fe, **kw))  # params as Snakemake would store them: text in key order


def test_job_params_do_not_depend_on_the_order_of_keys(repo_root):
    config = _config(repo_root)
    fe, backwards = _fe(config), _fe({**config, "fe": _reversed(config["fe"])})
    assert list(backwards.scenes) == list(reversed(list(fe.scenes)))  # the reversal does reorder
    for kw in (
        {"scenes": list(fe.scenes), "reading": "counterclockwise", "sections": ["cross_scene"]},
        {"scenes": ["section9_kinematic_0p5mm_s"], "sections": ["sweeps", "stability"]},
    ):
        assert _params(backwards, **kw) == _params(fe, **kw)


def test_job_params_hold_the_resolved_scenes_and_only_the_named_sections(repo_root):
    config = _config(repo_root)
    fe = _fe(config)
    job = job_config(fe, scenes=["section11_penalty_15p2rpm"], reading="counterclockwise")
    assert set(job) == {"scenes"}
    resolved = scene_mapping(fe, "section11_penalty_15p2rpm", "counterclockwise")
    assert as_mapping(FeJob.model_validate(job).scenes["section11_penalty_15p2rpm"]) == resolved
    assert resolved["solver"]["t_end"] == fe.control_readings_t_end  # a control reading's window
    reduced = {**config["fe"]["reduced"], "safety_factor": 0.3}
    changed = _fe({**config, "fe": {**config["fe"], "control_readings_t_end": 0.2, "reduced": reduced}})
    assert _params(changed, scenes=list(fe.scenes)) == _params(fe, scenes=list(fe.scenes))


def test_the_long_run_switch_sets_every_window_the_scenes_and_the_comparison_run(repo_root):
    config = _config(repo_root)
    fe = _fe({**config, "fe_long_runs": True})
    long = config["fe"]["long_runs"]
    for reading in fe.readings:
        scene = scene_mapping(fe, "section9_kinematic_0p5mm_s", reading)
        assert scene["solver"]["t_end"] == long["scene_t_end"]
    assert fe.comparison.t_end == long["comparison_t_end"]
    assert _fe(config).comparison.t_end == config["fe"]["comparison"]["t_end"]


def test_a_job_reads_its_sections_typed_and_refuses_an_unknown_one(repo_root):
    fe = _fe(_config(repo_root))
    job = FeJob.model_validate(job_config(fe, scenes=["section9_kinematic_0p5mm_s"], sections=["stability"]))
    assert job.stability == fe.stability and job.convergence is None
    with pytest.raises(ValueError, match="stabilty"):
        FeJob.model_validate({"scenes": {}, "stabilty": {}})
