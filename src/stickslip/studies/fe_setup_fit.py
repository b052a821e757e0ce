"""The FIT of a tip support to the paper's Fig. 21 centre: a penalty scene whose support stiffness the
closed form sets, run and labelled as a fit (not the stated setup)."""

from __future__ import annotations

from collections.abc import Mapping

import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe import mechanics as mc
from ..fe.params import BeamParams, FrictionTable
from ..fe.quantities import INTERPRETATION
from ..schema.fe import FeJob
from .fe_config import as_mapping, deep_merge
from .fe_scene import scene_dataset

FIT_LABEL = (
    "FIT, not the stated setup: the tip rests on a soft support (penalty contact) whose stiffness the closed "
    "form stickslip.fe.mechanics.soft_support_for_corner_displacement sets so that the static contact-corner "
    "offset equals the paper's Fig. 21 centre; everything else as the base scene"
)


def setup_fit_mapping(job: FeJob, base: str, centre: float) -> tuple[dict, float]:
    """(scene mapping, support stiffness [N mm-1]) of the tip-support fit to Fig. 21's centre [mm]."""
    mp = as_mapping(job.scenes[base])
    b = BeamParams.from_mapping(mp.get("beam", {}))
    q = mc.distributed_weight(b.rho, b.area, b.g)
    k = mc.soft_support_for_corner_displacement(abs(centre), q, b.length, b.E * b.inertia, b.thickness)
    return deep_merge(mp, {"contact": {"method": "penalty", "penalty_stiffness": k}}), k


def setup_fit_dataset(mapping: Mapping, friction: FrictionTable, stiffness: float) -> xr.Dataset:
    """The fitted setup's scene dataset, labelled as a fit."""
    ds = scene_dataset(mapping, friction, "setup_fit")
    ds["tip_support_stiffness"] = cf_variable((), stiffness, "N mm-1", "fitted tip support stiffness")
    ds.attrs["title"] = "Beam on rotating rigid disc: FIT of the tip support to Fig. 21"
    ds.attrs["model_interpretation"] = FIT_LABEL + ". " + INTERPRETATION
    return ds
