"""Stability of steady sliding (``fe.stability``): the eigenvalue map over contact angle x friction slope,
and explicit-transient cross-checks of chosen points."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import xarray as xr

from ..analysis.metrics import cf_variable
from ..fe.explicit import static_state
from ..fe.params import FrictionTable, SolverParams
from ..fe.quantities import INTERPRETATION, cf_attrs
from ..fe.stability import max_growth, sliding_eigenvalues, sliding_state, transient_growth
from ..schema.fe import FeJob, Stability
from .fe_config import as_mapping, deep_merge
from .fe_scene import scene_of

MAP_DIMS = ("contact_angle", "friction_slope")


def rayleigh_damping(mapping: Mapping) -> dict:
    """The scene's Rayleigh damping as keyword arguments of the eigen and transient analyses."""
    solver = SolverParams.from_mapping(mapping.get("solver", {}))
    return {"mass_damping": solver.mass_damping, "stiffness_damping": solver.stiffness_damping}


def at_angle(base: Mapping, angle: float) -> dict:
    return deep_merge(base, {"contact": {"angle_deg": angle}})


def growth_map(base: Mapping, angles, slopes, friction: FrictionTable, damp: Mapping):
    """Largest growth rate [s-1] and its frequency [Hz] per (angle, slope)."""
    g = np.zeros((len(angles), len(slopes)))
    fr = np.zeros_like(g)
    for i, a in enumerate(angles):
        sc = scene_of(at_angle(base, a), friction)
        for j, s in enumerate(slopes):
            g[i, j], fr[i, j] = max_growth(sliding_eigenvalues(sc.system, sc.law, slope=s, **damp))
    return g, fr


def crosscheck_point(base, friction, speed, angle, slope, st: Stability, damp: Mapping) -> dict:
    """One cross-check: with a linear friction law of ``slope`` through the table's value at the disc
    ``speed``, the eigenvalue growth (sliding and static normal force), both normal forces, and the growth
    of an explicit transient over ``crosscheck_e_folds`` e-foldings (at most ``crosscheck_max_t_end``)."""
    lin = FrictionTable.linear(friction(speed) - slope * speed, slope, 2.0 * speed)
    sc = scene_of(at_angle(base, angle), lin)
    ge, fe = max_growth(sliding_eigenvalues(sc.system, sc.law, **damp))
    dur = min(st.crosscheck_max_t_end, st.crosscheck_e_folds / ge)
    gt, ft = transient_growth(sc.system, sc.law, dur, **damp) if ge > 0 else (np.nan, np.nan)
    return {
        "eig": ge,
        "eig_f": fe,
        "eig_static": max_growth(sliding_eigenvalues(sc.system, sc.law, normal_force="static", **damp))[0],
        "N_static": static_state(sc.system, sc.law)[1],
        "N_slide": sliding_state(sc.system, sc.law)[1],
        "tr": gt,
        "tr_f": ft,
    }


def _cc_var(v, units, long_name):
    return cf_variable("crosscheck", np.array(v, float), units, long_name)


def crosscheck_variables(cc: list, rows: list[dict]) -> dict:
    """The cross-checks' variables along ``crosscheck``, and their largest relative difference."""
    col = {
        k: [r[k] for r in rows] for k in ("eig", "eig_f", "eig_static", "tr", "tr_f", "N_static", "N_slide")
    }
    eig, tr = np.array(col["eig"], float), np.array(col["tr"], float)
    rel = np.abs(tr / eig - 1)
    return {
        "crosscheck_eigen_growth_rate": _cc_var(eig, "s-1", "eigenvalue growth rate (sliding normal force)"),
        "crosscheck_eigen_growth_rate_static_normal": _cc_var(
            col["eig_static"], "s-1", "eigenvalue growth rate with the static normal force (old analysis)"
        ),
        "crosscheck_eigen_frequency": _cc_var(col["eig_f"], "Hz", "frequency of the least stable eigenvalue"),
        "crosscheck_transient_growth_rate": _cc_var(tr, "s-1", "growth rate fitted to an explicit transient"),
        "crosscheck_transient_frequency": _cc_var(
            col["tr_f"], "Hz", "dominant frequency of the growing transient (the mode that grows)"
        ),
        "crosscheck_relative_difference": _cc_var(rel, "1", "|transient / eigenvalue growth rate - 1|"),
        "crosscheck_static_normal_force": _cc_var(col["N_static"], "N", "static normal force (no friction)"),
        "crosscheck_sliding_normal_force": _cc_var(
            col["N_slide"], "N", "normal force in steady sliding (friction preload included)"
        ),
        "crosscheck_angle": _cc_var([c[0] for c in cc], "degree", "cross-check contact angle"),
        "crosscheck_slope": _cc_var([c[1] for c in cc], "s mm-1", "cross-check friction slope"),
        "crosscheck_max_relative_difference": cf_variable(
            (),
            float(np.nanmax(rel)) if rel.size else np.nan,
            "1",
            "largest |transient / eigenvalue growth rate - 1| of the cross-checks",
        ),
    }


def map_variables(g: np.ndarray, fr: np.ndarray) -> dict:
    return {
        "max_growth_rate": cf_variable(MAP_DIMS, g, "s-1", "largest real part of the linearised eigenvalues"),
        "unstable_frequency": cf_variable(MAP_DIMS, fr, "Hz", "frequency of the least stable eigenvalue"),
    }


def map_coords(angles, slopes) -> dict:
    return {
        "contact_angle": cf_variable("contact_angle", np.array(angles, float), "degree", "contact angle"),
        "friction_slope": cf_variable("friction_slope", np.array(slopes, float), "s mm-1", "d mu / d v_r"),
    }


def _nearest(angles, slopes, table_slope: float) -> tuple[int, int]:
    """(index of the mapped angle nearest 0, of the mapped slope nearest ``table_slope``)."""
    return int(np.argmin(np.abs(np.array(angles)))), int(np.argmin(np.abs(np.array(slopes) - table_slope)))


def at_table_slope(g, fr, angles, slopes, table_slope: float) -> dict:
    """Growth rate and frequency at angle 0 and the mapped slope nearest the table's."""
    a0, k0 = _nearest(angles, slopes, table_slope)
    return {
        "growth_rate_at_table_slope_angle0": cf_variable(
            (), g[a0, k0], "s-1", "growth rate at angle 0 and the slope nearest the table's"
        ),
        "unstable_frequency_at_table_slope_angle0": cf_variable(
            (), fr[a0, k0], "Hz", "frequency of the least stable mode at angle 0 and the table's slope"
        ),
    }


def at_speed(g, angles, slopes, table_slope: float, label: str, speed: float) -> dict:
    """Growth rate at angle 0 and the mapped slope nearest the table's slope at one disc speed, named by that
    speed's label, so a claim reading it names the speed it is decided at."""
    a0, k0 = _nearest(angles, slopes, table_slope)
    where = f"at {speed:.3g} mm/s (table slope {table_slope:.3g} s/mm, mapped {slopes[k0]:.3g})"
    return {
        f"growth_rate_angle0_{label}": cf_variable((), g[a0, k0], "s-1", f"growth rate at angle 0 {where}"),
        f"table_slope_{label}": cf_variable((), table_slope, "s mm-1", f"d mu / d v_r of the table {where}"),
    }


def stability_dataset(job: FeJob, friction: FrictionTable) -> xr.Dataset:
    """Eigenvalue map over contact angle x friction slope, and explicit-transient cross-checks.

    Linearised about steady sliding with the sliding normal force (friction preload included) and the
    base scene's Rayleigh damping. Each cross-check runs the explicit integrator from the sliding state
    for ``crosscheck_e_folds`` e-foldings of the eigenvalue growth rate (at most
    ``crosscheck_max_t_end``) with a linear friction law of the cross-check slope."""
    st = job.stability
    base = as_mapping(job.scenes[st.base])
    angles, slopes = list(st.angles), list(st.slopes)
    damp = rayleigh_damping(base)
    g, fr = growth_map(base, angles, slopes, friction, damp)
    V = scene_of(base, friction).params.disc.surface_speed
    cc = st.crosscheck
    rows = [crosscheck_point(base, friction, V, a, s, st, damp) for a, s in cc]
    table_slope = {
        "table_slope_at_disc_speed": cf_variable(
            (), friction.slope(V), "s mm-1", "d mu / d v_r of the friction table at the disc speed"
        )
    }
    ds = xr.Dataset(
        {**map_variables(g, fr), **crosscheck_variables(cc, rows), **table_slope},
        coords=map_coords(angles, slopes),
    )
    ds = ds.assign(at_table_slope(g, fr, angles, slopes, friction.slope(V)))
    for label, scene in sorted(st.speeds.items()):
        speed = scene_of(as_mapping(job.scenes[scene]), friction).params.disc.surface_speed
        ds = ds.assign(at_speed(g, angles, slopes, friction.slope(speed), label, speed))
    ds.attrs.update(
        cf_attrs(
            "Stability of steady sliding (complex eigenvalues)",
            model_interpretation=INTERPRETATION,
            base_scene=st.base,
            method="linearisation about steady sliding (sliding normal force, friction slope, Rayleigh "
            "damping); cross-check by explicit transients from the sliding state",
        )
    )
    return ds
