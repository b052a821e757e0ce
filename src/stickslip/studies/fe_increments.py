"""Explicit increment counts of the continuum strip per mesh, time-step factor and damping (``fe.increments``;
the paper's banner: 3 688 747 increments at 0.65 s)."""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe.params import FrictionTable, SceneParams
from ..fe.quantities import cf_attrs
from ..schema.fe import FeJob
from .fe_config import as_mapping


def increments_dataset(job: FeJob, duration: float = 0.65) -> xr.Dataset:
    """Increment count of the continuum strip for ``duration`` (the paper's banner: 3 688 747 at 0.65 s)
    for each mesh x safety factor x stiffness damping of ``fe.increments``, from its global stable step."""
    from ..fe.continuum import build_continuum, increments, stable_time_step

    inc = job.increments
    meshes, safety_factors, betas = inc.meshes, inc.safety_factors, inc.betas
    p = SceneParams.from_mapping(as_mapping(job.scenes[inc.base]))
    fr = FrictionTable.paper_fig17()
    n = np.zeros((len(meshes), len(safety_factors), len(betas)))
    dtc = np.zeros((len(meshes), len(betas)))
    for i, (nx, ny) in enumerate(meshes):
        for k, beta in enumerate(betas):
            sc = build_continuum(p.beam, p.disc, p.contact, fr, nx=nx, ny=ny, damping_beta=beta)
            dtc[i, k] = stable_time_step(sc)
            for j, sf in enumerate(safety_factors):
                n[i, j, k] = increments(sc, duration, sf)
    ds = xr.Dataset(
        {
            "increments": cf_variable(
                ("mesh", "safety_factor", "stiffness_damping"),
                n,
                "1",
                f"explicit increments to reach {duration} s",
            ),
            "stable_time_step": cf_variable(
                ("mesh", "stiffness_damping"), dtc, "s", "global stable time step 2/omega_max (damped)"
            ),
            "mesh_nx": cf_variable("mesh", np.array([m[0] for m in meshes]), "1", "elements along"),
            "mesh_ny": cf_variable("mesh", np.array([m[1] for m in meshes]), "1", "elements across"),
        },
        coords={
            "mesh": ("mesh", [f"{a}x{b}" for a, b in meshes], {"long_name": "mesh (along x across)"}),
            "safety_factor": ("safety_factor", np.array(safety_factors, float), {"units": "1"}),
            "stiffness_damping": ("stiffness_damping", np.array(betas, float), {"units": "s"}),
        },
    )
    i0 = [f"{a}x{b}" for a, b in meshes].index("100x1") if (100, 1) in [tuple(m) for m in meshes] else 0
    j0 = int(np.argmin(np.abs(np.array(safety_factors, float) - 1.0)))
    ds["increments_0p65s_100x1"] = cf_variable(
        (), float(n[i0, j0, 0]), "1", "increments for 0.65 s, continuum 100x1, full stable step, no damping"
    )
    ds.attrs.update(
        cf_attrs(
            "Explicit increment counts of the continuum strip",
            model_interpretation="plane-stress CPS4I-kind strip, lumped mass; global stable step",
            method="dt = safety_factor * 2/omega_max (sqrt(1+xi^2)-xi); increments = ceil(duration/dt)",
        )
    )
    return ds
