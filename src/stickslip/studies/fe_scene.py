"""One beam-on-disc scene from its resolved config mapping: the run (stickslip.fe.run) and its dataset."""

from __future__ import annotations

import json
from collections.abc import Mapping

import xarray as xr

from ..fe.params import FrictionTable, SceneParams
from ..fe.quantities import INTERPRETATION, cf_attrs
from ..fe.run import integrate_scene, run_metrics
from ..fe.scene import BuiltScene, build_scene
from ..schema.fe import FeOutput
from .fe_packing import result_dataset, shape_variables


def scene_of(mapping: Mapping, friction: FrictionTable) -> BuiltScene:
    """The built scene of a resolved scene mapping (its beam, disc, contact and solver sections)."""
    return build_scene(SceneParams.from_mapping(mapping), friction)


def run_scene(
    mapping: Mapping,
    friction: FrictionTable,
    *,
    duration: float | None = None,
    reduced: Mapping | None = None,
    progress=None,
    midspan: bool = False,
):
    """Run one scene (full FE, or Craig-Bampton reduced if ``reduced`` is given).

    ``progress(done, total)`` is passed to the integrator (time steps done out of total). ``midspan``
    (full model only): also record the mid-span node's vertical motion, a node off the contact
    (``result.extra['midspan']`` and the metrics ``midspan_*``).

    Returns (result, metrics, scene).
    """
    scene = scene_of(mapping, friction)
    r = integrate_scene(scene, duration=duration, reduced=reduced, progress=progress, midspan=midspan)
    return r, run_metrics(scene, r), scene


def scene_dataset(mapping: Mapping, friction: FrictionTable, name: str = "", progress=None) -> xr.Dataset:
    """Pure build of one scene's dataset from its merged config mapping (the ensemble contract:
    ``build(mapping) -> xr.Dataset``). ``mapping['output']`` may give ``windows`` (list of [t0, t1] s)
    and ``bin_width`` [s]; ``progress(done, total)`` sees the time steps (``run_scene``)."""
    r, m, scene = run_scene(mapping, friction, midspan=True, progress=progress)
    out = FeOutput.model_validate(mapping.get("output", {}))
    ds = result_dataset(r, m, windows=out.windows, bin_width=out.bin_width)
    ds = ds.assign(shape_variables(scene, r.q_static))
    ds.attrs.update(
        cf_attrs(
            f"Beam on rotating rigid disc, scene {name}".strip(),
            scene=name,
            parameters=json.dumps({k: v.model_dump() for k, v in vars(scene.params).items()}),
            model_interpretation=INTERPRETATION,
            method=f"explicit central difference (compiled kernel), {scene.law.method} contact, "
            f"dt={r.dt:.6g} s (stable limit {r.dt_crit:.6g} s)",
            diverged=int(r.extra.get("diverged", False)),
        )
    )
    return ds
