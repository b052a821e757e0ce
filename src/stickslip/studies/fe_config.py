"""The typed ``fe`` section (``stickslip.schema.Fe``) resolved for one run or job: scenes merged over the
defaults and a reading, the long-run switch, the part of the section a job reads (its params, typed again by
``FeJob`` in the job), and the windows the comparison and the step-halving runs use.

A resolved scene is a mapping: it is what the perturbation ensemble perturbs (by field path) and what
``SceneParams.from_mapping`` turns into the run's typed parameters.
"""

from __future__ import annotations

import copy
from collections.abc import Mapping

from ..fe.params import SolverParams
from ..fe.step_halving import HALF_STEP
from ..schema import PipelineConfig
from ..schema.base import canonical
from ..schema.fe import Fe, FeJob, FeScene

#: The fields of an FE mapping (a scene's, or the ``fe`` section a study reads) that the perturbation
#: ensemble perturbs (stickslip.ensemble.declared): the physical parameters and the numerical settings.
#: Never the windows and samplings of the output (t_end, output_dt, bin_width, windows, e-fold budgets) nor
#: counts (element numbers, meshes), nor the increment study's grid (a safety factor of 1 is its bound, and
#: the study never read its members' grid: their base scene is what moves).
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


def as_mapping(scene: FeScene) -> dict:
    """A scene's given values as a mapping (what the ensemble perturbs and ``SceneParams`` reads)."""
    return scene.model_dump(exclude_none=True)


def _layer(scene: FeScene) -> dict:
    """The values a layer of a scene sets itself (a field's schema default is no setting of the layer)."""
    return scene.model_dump(exclude_unset=True, exclude_none=True)


def scene_mapping(fe: Fe, name: str, reading: str | None = None) -> dict:
    """defaults <- reading <- scene, and for every reading but the first (the default) its window
    ``fe.control_readings_t_end``. ``reading`` None: the first of ``fe.readings``.

    A reading fixes how the paper's ambiguous geometry is read (contact face, node 1, disc direction,
    start); a scene sets what the paper varies (contact method, disc speed, angle)."""
    if name not in fe.scenes:
        raise ValueError(f"scenes.{name}: no such scene")
    default = next(iter(fe.readings))
    reading = default if reading is None else reading
    if reading not in fe.readings:
        raise ValueError(f"readings.{reading}: no such FE reading ({sorted(fe.readings)})")
    over = {k: v for k, v in _layer(fe.readings[reading]).items() if k != "description"}
    merged = deep_merge(deep_merge(_layer(fe.defaults), over), _layer(fe.scenes[name]))
    if reading != default:  # a control reading's window
        merged = deep_merge(merged, {"solver": {"t_end": fe.control_readings_t_end}})
    return as_mapping(FeScene.model_validate(merged))


def effective_fe(config: PipelineConfig) -> Fe:
    """The ``fe`` section with the long-run switch applied: ``fe_long_runs: true`` runs the scenes of every
    reading for ``fe.long_runs.scene_t_end`` (the paper's 1 s; by default only the first reading does) and
    the model comparison for ``fe.long_runs.comparison_t_end`` (the paper's 0.65 s)."""
    fe = config.fe
    if not config.fe_long_runs:
        return fe
    t_end = fe.long_runs.scene_t_end
    defaults = deep_merge(_layer(fe.defaults), {"solver": {"t_end": t_end}})
    comparison = fe.comparison.model_copy(update={"t_end": fe.long_runs.comparison_t_end})
    return fe.model_copy(
        update={
            "defaults": FeScene.model_validate(defaults),
            "control_readings_t_end": t_end,  # the control readings' short window too
            "comparison": comparison,
        }
    )


def job_config(fe: Fe, *, scenes=(), reading: str | None = None, sections=()) -> dict:
    """The part of the (effective) ``fe`` section one job reads, resolved: every named scene merged over
    the defaults and the reading (``scene_mapping``; None: the first reading), plus the named sections;
    keys sorted at every level. A rule passes this as its params, so a value re-runs exactly the jobs that
    read it, and a reordering of keys in a file re-runs nothing; the job reads it as a ``FeJob``."""
    out = {"scenes": {name: scene_mapping(fe, name, reading) for name in scenes}}
    out.update(fe.model_dump(include=set(sections), exclude_none=True))
    return canonical(out)


def study_job(member: Mapping, section: str) -> FeJob:
    """One study's part of a job's (perturbed) params, typed: the scenes and ``section``. The ensemble moves
    every declared field by its relative step, one on its bound included (a safety factor of 1), so each
    study checks only what it reads, as its runs check it."""
    return FeJob.model_validate({"scenes": member["scenes"], section: member[section]})


def with_t_end(mapping: Mapping, t_end: float) -> dict:
    """A resolved scene over another window ``t_end`` [s]."""
    return deep_merge(mapping, {"solver": {"t_end": t_end}})


def comparison_mapping(job: FeJob, name: str) -> dict:
    """The job's scene with the model comparison's duration."""
    return with_t_end(as_mapping(job.scenes[name]), job.comparison.t_end)


def window_mapping(job: FeJob, name: str) -> dict:
    """The job's scene over its claim window ``comparison.claim_windows[name]``: the continuum's run over
    the window of the claims its comparison rows license."""
    windows = job.comparison.claim_windows
    if name not in windows:
        raise ValueError(f"comparison.claim_windows.{name}: no such claim window ({sorted(windows)})")
    return with_t_end(as_mapping(job.scenes[name]), windows[name])


def halved_step(mapping: Mapping) -> dict:
    """The scene mapping with its explicit time step halved (safety factor x 0.5)."""
    sf = SolverParams.from_mapping(mapping.get("solver", {})).safety_factor
    return deep_merge(mapping, {"solver": {"safety_factor": HALF_STEP * sf}})
