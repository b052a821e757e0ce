"""Each FE job's params are the resolved part of the fe config it reads (studies.fe_config.job_config):
the order of keys in a file, and keys the job does not read, leave them unchanged (so Snakemake re-runs
nothing)."""

import json

from stickslip.pipeline.config import load_config
from stickslip.studies.fe_config import effective_fe_config, job_config, scene_mapping


def _fe(repo_root):
    return effective_fe_config(load_config(sorted((repo_root / "config").glob("*.yaml"))))


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
    fe = _fe(repo_root)
    for kw in (
        {"scenes": list(fe["scenes"]), "reading": "counterclockwise", "sections": ["cross_scene"]},
        {"scenes": ["section9_kinematic_0p5mm_s"], "sections": ["sweeps", "stability"]},
    ):
        assert list(_reversed(fe)) == list(reversed(list(fe)))  # the reversal does reorder
        assert _params(_reversed(fe), **kw) == _params(fe, **kw)


def test_job_params_hold_the_resolved_scenes_and_only_the_named_sections(repo_root):
    fe = _fe(repo_root)
    job = job_config(fe, scenes=["section11_penalty_15p2rpm"], reading="counterclockwise")
    assert set(job) == {"scenes"}
    resolved = scene_mapping(fe, "section11_penalty_15p2rpm", "counterclockwise")
    assert scene_mapping(job, "section11_penalty_15p2rpm") == resolved
    assert resolved["solver"]["t_end"] == fe["control_readings_t_end"]  # a control reading's window
    changed = {**fe, "control_readings_t_end": 0.2, "reduced": {"safety_factor": 0.3}}
    assert _params(changed, scenes=list(fe["scenes"])) == _params(fe, scenes=list(fe["scenes"]))
