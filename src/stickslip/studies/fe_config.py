"""The ``fe`` config resolved for one run or job: scenes merged over the defaults and a reading, the
long-run switch, the part of the section a job reads (its params), and the windows the comparison and the
step-halving runs use.

Config layout (``fe:`` key): ``defaults`` (beam/solver/contact/disc mappings merged under every scene),
``readings``, ``scenes`` (name -> partial mapping), ``sweeps``, ``convergence``, ``stability``, ``reduced``.
"""

from __future__ import annotations

import copy
from collections.abc import Mapping

from ..fe.params import DEFAULT_SAFETY_FACTOR
from ..fe.step_halving import HALF_STEP

#: The fields of an FE mapping (a scene's, or the ``fe`` section a study reads) that the perturbation
#: ensemble perturbs (stickslip.ensemble.declared): the physical parameters and the numerical settings.
#: Never the windows and samplings of the output (t_end, output_dt, bin_width, windows, e-fold budgets) nor
#: counts (element numbers, meshes).
PERTURBED_FIELDS = (
    "beam.length",
    "beam.thickness",
    "beam.width",
    "beam.youngs_modulus_gpa",
    "beam.density_kg_m3",
    "beam.poisson_ratio",
    "beam.gravity_m_s2",
    "disc.diameter",
    "disc.speed_rev_per_min",
    "disc.surface_speed_mm_s",
    "contact.angle_deg",
    "contact.penalty_stiffness",
    "solver.safety_factor",
    "solver.mass_damping",
    "solver.stiffness_damping",
    "sweeps.*.values",
    "stability.angles",
    "stability.slopes",
    "stability.crosscheck",
    "convergence.safety_factors",
    "increments.safety_factors",
    "increments.betas",
)


def deep_merge(a: Mapping, b: Mapping) -> dict:
    out = copy.deepcopy(dict(a))
    for k, v in b.items():
        out[k] = (
            deep_merge(out[k], v)
            if isinstance(v, Mapping) and isinstance(out.get(k), Mapping)
            else copy.deepcopy(v)
        )
    return out


def scene_mapping(fe_cfg: Mapping, name: str, reading: str | None = None) -> dict:
    """defaults <- reading <- scene, and for every reading but the first (the default) its window
    ``fe_cfg['control_readings_t_end']`` where given. ``reading`` None: the first of ``fe_cfg['readings']``.

    A reading fixes how the paper's ambiguous geometry is read (contact face, node 1, disc direction,
    start); a scene sets what the paper varies (contact method, disc speed, angle)."""
    if name not in fe_cfg.get("scenes", {}):
        raise ValueError(f"scenes.{name}: no such scene")
    readings = fe_cfg.get("readings", {}) or {}
    if reading is None and readings:
        reading = next(iter(readings))
    if reading is not None and reading not in readings:
        raise ValueError(f"readings.{reading}: no such FE reading ({sorted(readings)})")
    over = dict(readings.get(reading, {}) or {}) if reading else {}
    over.pop("description", None)
    merged = deep_merge(deep_merge(fe_cfg.get("defaults", {}), over), fe_cfg["scenes"][name])
    control = fe_cfg.get("control_readings_t_end")
    if control is not None and reading is not None and reading != next(iter(readings)):
        merged = deep_merge(merged, {"solver": {"t_end": float(control)}})  # a control reading's window
    return merged


def effective_fe_config(config: Mapping) -> dict:
    """The ``fe`` config with the long-run switch applied: top-level ``fe_long_runs: true`` runs the scenes
    of every reading for ``fe.long_runs.scene_t_end`` (the paper's 1 s; by default only the first reading
    does) and the model comparison for ``fe.long_runs.comparison_t_end`` (the paper's 0.65 s)."""
    fe = copy.deepcopy(dict(config["fe"]))
    if config.get("fe_long_runs", False):
        lr = fe.get("long_runs", {})
        t_end = float(lr["scene_t_end"])
        fe.setdefault("defaults", {}).setdefault("solver", {})["t_end"] = t_end
        fe["control_readings_t_end"] = t_end  # the control readings' short window too
        fe.setdefault("comparison", {})["t_end"] = float(lr["comparison_t_end"])
    return fe


def canonical(node):
    """A nested mapping with its keys sorted at every level (lists keep their order)."""
    if isinstance(node, Mapping):
        return {k: canonical(node[k]) for k in sorted(node, key=str)}
    if isinstance(node, (list, tuple)):
        return [canonical(v) for v in node]
    return node


def job_config(fe_cfg: Mapping, *, scenes=(), reading: str | None = None, sections=()) -> dict:
    """The part of the (effective) ``fe`` config one job reads, resolved: every named scene merged over the
    defaults and the reading (``scene_mapping``; None: the first reading), plus the named sections as they
    are; keys sorted at every level. A rule passes this as its params, so a value re-runs exactly the jobs
    that read it, and a reordering of keys in a file re-runs nothing. ``scene_mapping(job, name)`` returns
    the resolved scene again (the result has no defaults or readings left to merge)."""
    out = {"scenes": {name: scene_mapping(fe_cfg, name, reading) for name in scenes}}
    out.update({key: fe_cfg[key] for key in sections})
    return canonical(out)


def comparison_mapping(fe_cfg: Mapping, name: str) -> dict:
    """Scene mapping (default reading) with the model comparison's duration."""
    return deep_merge(scene_mapping(fe_cfg, name), {"solver": {"t_end": fe_cfg["comparison"]["t_end"]}})


def window_mapping(fe_cfg: Mapping, name: str) -> dict:
    """Scene mapping (default reading) over the claim window ``fe_cfg['comparison']['claim_windows']
    [name]``: the continuum's run over the window of the claims its comparison rows license."""
    windows = fe_cfg["comparison"].get("claim_windows") or {}
    if name not in windows:
        raise ValueError(f"comparison.claim_windows.{name}: no such claim window ({sorted(windows)})")
    return deep_merge(scene_mapping(fe_cfg, name), {"solver": {"t_end": float(windows[name])}})


def halved_step(mapping: Mapping) -> dict:
    """The scene mapping with its explicit time step halved (safety factor x 0.5)."""
    sf = float((mapping.get("solver", {}) or {}).get("safety_factor", DEFAULT_SAFETY_FACTOR))
    return deep_merge(mapping, {"solver": {"safety_factor": HALF_STEP * sf}})
