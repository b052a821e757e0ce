"""Scene, sweep, convergence and stability runs of the beam-on-disc model, returned as xarray Datasets.

Config layout (``fe:`` key): ``defaults`` (beam/solver/contact/disc mappings merged under every scene),
``scenes`` (name -> partial mapping), ``sweeps``, ``convergence``, ``stability``, ``reduced``.
"""

from __future__ import annotations

import copy
import dataclasses
import json
from collections.abc import Mapping

import numpy as np
import xarray as xr

from .beam import cantilever_axial_frequencies, cantilever_bending_frequencies, modal_analysis
from .explicit import integrate
from .metrics import trajectory_metrics, trend_sign, window_envelope
from .params import FrictionTable
from .reduced import contact_boundary, craig_bampton
from .scene import SceneParams, build_scene
from .stability import max_growth, sliding_eigenvalues, transient_growth_rate

INTERPRETATION = (
    "2-D Euler-Bernoulli frame elements (axial + bending), clamped left end, steel E=210 GPa rho=7850 kg/m3, "
    "out-of-plane width as stated (gravity-only normal load: contact pressure independent of width, "
    "frequencies independent of width, forces proportional to it); rigid disc, small-displacement contact "
    "at the free end with fixed normal/tangent; contact angle = tilt of the disc normal at the contact "
    "towards the clamp; mu(|v_r|) from the tabulated friction law with static limit mu(0) and exact stick; "
    "displacements measured from the gravity equilibrium in contact; no material damping."
)

UNITS = {
    "max_horizontal_displacement": ("mm", "maximum horizontal displacement of node 1"),
    "min_horizontal_displacement": ("mm", "minimum horizontal displacement of node 1"),
    "mean_horizontal_displacement": ("mm", "mean horizontal displacement of node 1 (second half)"),
    "abs_mean_horizontal_displacement": ("mm", "absolute mean horizontal displacement (second half)"),
    "horizontal_amplitude": ("mm", "half peak-to-peak horizontal displacement (second half)"),
    "max_vertical_displacement": ("mm", "maximum absolute vertical displacement of node 1"),
    "vertical_amplitude": ("mm", "half peak-to-peak vertical displacement (second half)"),
    "max_abs_horizontal_velocity": ("mm s-1", "maximum absolute horizontal velocity of node 1"),
    "max_abs_vertical_velocity": ("mm s-1", "maximum absolute vertical velocity of node 1"),
    "dominant_frequency": ("Hz", "dominant frequency of the horizontal displacement"),
    "vertical_dominant_frequency": ("Hz", "dominant frequency of the vertical displacement"),
    "stick_fraction": ("1", "fraction of increments in stick (second half of the run)"),
    "slip_fraction": ("1", "fraction of increments in slip (second half of the run)"),
    "separation_fraction": ("1", "fraction of increments separated (second half of the run)"),
    "stick_fraction_whole_run": ("1", "fraction of increments in stick (whole run)"),
    "separation_fraction_whole_run": ("1", "fraction of increments separated (whole run)"),
    "static_normal_force": ("N", "static contact normal force (gravity only)"),
    "max_normal_force_ratio": ("1", "maximum normal force over static normal force"),
    "stable_time_step": ("s", "central-difference stability limit 2/omega_max"),
    "time_step": ("s", "time step used"),
    "increment_count": ("1", "number of increments"),
    "increment_count_0p65s": ("1", "number of increments to reach 0.65 s"),
    "cpu_time": ("s", "CPU time of the time loop"),
    "stick_end_time": ("s", "time of the last stick sample"),
    "first_stick_duration": ("s", "duration of the initial stick phase"),
    "horizontal_vertical_correlation": ("1", "correlation of horizontal and vertical displacement"),
    "horizontal_amplitude_growth_ratio": ("1", "last-window over second-window horizontal half peak-to-peak"),
    "horizontal_nearest_mode_ratio": ("1", "horizontal dominant frequency over nearest natural frequency"),
    "vertical_nearest_mode_ratio": ("1", "vertical dominant frequency over nearest natural frequency"),
    "disc_surface_speed": ("mm s-1", "disc surface speed at the contact"),
    "horizontal_velocity_trend": ("1", "sign of the trend of the horizontal velocity envelope"),
    "vertical_velocity_trend": ("1", "sign of the trend of the vertical velocity envelope"),
    "horizontal_displacement_trend": ("1", "sign of the trend of the horizontal displacement envelope"),
}


def deep_merge(a: Mapping, b: Mapping) -> dict:
    out = copy.deepcopy(dict(a))
    for k, v in b.items():
        out[k] = (
            deep_merge(out[k], v)
            if isinstance(v, Mapping) and isinstance(out.get(k), Mapping)
            else copy.deepcopy(v)
        )
    return out


def scene_mapping(fe_cfg: Mapping, name: str) -> dict:
    if name not in fe_cfg.get("scenes", {}):
        raise ValueError(f"scenes.{name}: no such scene")
    return deep_merge(fe_cfg.get("defaults", {}), fe_cfg["scenes"][name])


def _natural_frequencies(scene) -> np.ndarray:
    """Natural frequencies [Hz] of the beam with the contact held (bilateral normal constraint)."""
    s = scene.system
    if scene.law.method == "fixed_normal" or not np.any(s.c_n):
        return modal_analysis(s.K, s.M, 40)[0]
    from .stability import _null

    Z = _null(s.c_n)
    return modal_analysis(Z.T @ s.K @ Z, Z.T @ s.M @ Z, 40)[0]


def run_scene(
    mapping: Mapping,
    friction: FrictionTable,
    *,
    duration: float | None = None,
    reduced: Mapping | None = None,
    progress=None,
):
    """Run one scene (full FE, or Craig-Bampton reduced if ``reduced`` is given).

    ``progress(done, total)`` is passed to the integrator (time steps done out of total).

    Returns (result, metrics, scene).
    """
    p = SceneParams.from_mapping(
        {k: v for k, v in mapping.items() if k in ("beam", "disc", "contact", "solver")}
    )
    scene = build_scene(p, friction)
    system = scene.system
    if reduced:
        mask = (scene.beam.free % 3) == 0
        system, _ = craig_bampton(
            system,
            contact_boundary(system),
            int(reduced.get("n_bending_modes", 4)),
            mask,
            int(reduced.get("n_axial_modes", 1)),
        )
    sp = p.solver
    r = integrate(
        system,
        scene.law,
        duration or sp.duration,
        safety_factor=float((reduced or {}).get("safety_factor", sp.safety_factor)),
        output_interval=sp.output_interval,
        initial_state=sp.initial_state,
        mass_damping=sp.mass_damping,
        stiffness_damping=sp.stiffness_damping,
        progress=progress,
    )
    m = trajectory_metrics(r, _natural_frequencies(scene))
    m["disc_surface_speed"] = p.disc.surface_speed
    _, evx = window_envelope(r.t, r.vx)
    _, evy = window_envelope(r.t, r.vy)
    _, ex = window_envelope(r.t, r.x - r.x[0])
    m["horizontal_velocity_trend"] = trend_sign(evx)
    m["vertical_velocity_trend"] = trend_sign(evy)
    m["horizontal_displacement_trend"] = trend_sign(ex)
    return r, m, scene


def scene_dataset(name: str, mapping: Mapping, r, m: Mapping, scene) -> xr.Dataset:
    x0, y0 = r.x[0], r.y[0]
    tw, evx = window_envelope(r.t, r.vx)
    _, evy = window_envelope(r.t, r.vy)
    _, ex = window_envelope(r.t, r.x - x0)
    _, ey = window_envelope(r.t, r.y - y0)
    ds = xr.Dataset(
        {
            "horizontal_displacement": (
                "time",
                r.x - x0,
                {"units": "mm", "long_name": "horizontal displacement of node 1 from gravity equilibrium"},
            ),
            "vertical_displacement": (
                "time",
                r.y - y0,
                {"units": "mm", "long_name": "vertical displacement of node 1 from gravity equilibrium"},
            ),
            "horizontal_velocity": (
                "time",
                r.vx,
                {"units": "mm s-1", "long_name": "horizontal velocity of node 1"},
            ),
            "vertical_velocity": (
                "time",
                r.vy,
                {"units": "mm s-1", "long_name": "vertical velocity of node 1"},
            ),
            "normal_force": ("time", r.normal_force, {"units": "N", "long_name": "contact normal force"}),
            "friction_force": (
                "time",
                r.friction_force,
                {"units": "N", "long_name": "friction force on the beam along the disc velocity"},
            ),
            "slip_velocity": (
                "time",
                r.slip_velocity,
                {"units": "mm s-1", "long_name": "beam minus disc tangential velocity"},
            ),
            "contact_state": (
                "time",
                r.state.astype("i1"),
                {
                    "units": "1",
                    "long_name": "contact state",
                    "flag_values": np.array([0, 1, 2], "i1"),
                    "flag_meanings": "separated stick slip",
                },
            ),
            "horizontal_velocity_envelope": (
                "window",
                evx,
                {"units": "mm s-1", "long_name": "half peak-to-peak horizontal velocity per window"},
            ),
            "vertical_velocity_envelope": (
                "window",
                evy,
                {"units": "mm s-1", "long_name": "half peak-to-peak vertical velocity per window"},
            ),
            "horizontal_displacement_envelope": (
                "window",
                ex,
                {"units": "mm", "long_name": "half peak-to-peak horizontal displacement per window"},
            ),
            "vertical_displacement_envelope": (
                "window",
                ey,
                {"units": "mm", "long_name": "half peak-to-peak vertical displacement per window"},
            ),
        },
        coords={
            "time": ("time", r.t, {"units": "s", "long_name": "time"}),
            "window_time": ("window", tw, {"units": "s", "long_name": "window centre time"}),
        },
    )
    nat = _natural_frequencies(scene)[:10]
    ds["natural_frequency"] = (
        "mode",
        nat,
        {"units": "Hz", "long_name": "natural frequencies with contact held"},
    )
    for k, v in m.items():
        u, ln = UNITS.get(k, ("1", k.replace("_", " ")))
        ds[k] = ((), v, {"units": u, "long_name": ln})
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": f"Beam on rotating rigid disc, scene {name}",
            "scene": name,
            "parameters": json.dumps(
                {
                    k: dataclasses.asdict(getattr(scene.params, k))
                    for k in ("beam", "disc", "contact", "solver")
                }
            ),
            "model_interpretation": INTERPRETATION,
            "method": (
                f"explicit central difference, {scene.law.method} contact, dt={r.dt:.6g} s "
                f"(stable limit {r.dt_crit:.6g} s)"
            ),
            "diverged": int(r.extra.get("diverged", False)),
        }
    )
    return ds


def sweep_dataset(fe_cfg: Mapping, sweep_name: str, friction: FrictionTable) -> xr.Dataset:
    sw = fe_cfg["sweeps"][sweep_name]
    base = scene_mapping(fe_cfg, sw["base"])
    path = sw["parameter"].split(".")
    rows = []
    for val in sw["values"]:
        mp = copy.deepcopy(base)
        mp.setdefault(path[0], {})[path[1]] = val
        if "duration" in sw:
            mp.setdefault("solver", {})["duration"] = sw["duration"]
        _, m, _ = run_scene(mp, friction)
        rows.append(m)
    coord = sw["coord"]
    keys = [k for k in rows[0] if np.isscalar(rows[0][k])]
    ds = xr.Dataset(
        {
            k: (
                coord,
                np.array([r[k] for r in rows], float),
                {"units": UNITS.get(k, ("1", k))[0], "long_name": UNITS.get(k, ("1", k))[1]},
            )
            for k in keys
        },
        coords={
            coord: (
                coord,
                np.array(sw["values"], float),
                {"units": sw.get("units", "1"), "long_name": sw.get("long_name", coord)},
            )
        },
    )
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": f"Beam-on-disc sweep {sweep_name}",
            "model_interpretation": INTERPRETATION,
            "base_scene": sw["base"],
            "parameters": json.dumps(base),
            "method": "explicit central difference, one run per sweep value",
        }
    )
    return ds


def convergence_dataset(fe_cfg: Mapping, friction: FrictionTable) -> xr.Dataset:
    cv = fe_cfg["convergence"]
    base = scene_mapping(fe_cfg, cv["base"])
    n_el = list(cv["n_elements"])
    out: dict[str, list] = {}
    for offset in (False, True):
        for n in n_el:
            mp = deep_merge(
                base,
                {
                    "beam": {"n_elements": n},
                    "contact": {"surface_offset": offset},
                    "solver": {"duration": cv["duration"]},
                },
            )
            _, m, scene = run_scene(mp, friction)
            bp = scene.params.beam
            from .beam import assemble_beam

            b = assemble_beam(bp)
            f, _ = modal_analysis(b.K, b.M, 12)
            fb = cantilever_bending_frequencies(bp, 3)
            fa = cantilever_axial_frequencies(bp, 1)[0]
            tag = "offset_" if offset else ""
            for k in (
                "dominant_frequency",
                "horizontal_amplitude",
                "vertical_amplitude",
                "stick_fraction",
                "slip_fraction",
                "separation_fraction",
                "stable_time_step",
            ):
                out.setdefault(tag + k, []).append(m[k])
            if not offset:
                from .beam import classify_modes

                fr, phi = modal_analysis(b.K, b.M)
                ax = classify_modes(phi, b.free)
                out.setdefault("bending_frequency_error", []).append(np.abs(fr[~ax][:3] / fb - 1))
                out.setdefault("axial_frequency_error", []).append(abs(fr[ax][0] / fa - 1))
    ds = xr.Dataset(
        coords={
            "n_elements": (
                "n_elements",
                np.array(n_el),
                {"units": "1", "long_name": "number of beam elements"},
            ),
            "bending_mode": (
                "bending_mode",
                np.arange(1, 4),
                {"units": "1", "long_name": "cantilever bending mode"},
            ),
        }
    )
    for k, v in out.items():
        u = (
            "Hz"
            if "frequency" in k and "error" not in k
            else ("s" if "time_step" in k else ("mm" if "amplitude" in k else "1"))
        )
        dims = ("n_elements", "bending_mode") if k == "bending_frequency_error" else ("n_elements",)
        ds[k] = (
            dims,
            np.array(v, float),
            {
                "units": u,
                "long_name": k.replace("_", " ")
                + (" (contact at lower face)" if k.startswith("offset_") else ""),
            },
        )
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": "Beam-on-disc element-count convergence",
            "model_interpretation": INTERPRETATION,
            "base_scene": cv["base"],
            "method": "explicit central difference; modal errors against closed-form cantilever",
        }
    )
    return ds


def stability_dataset(fe_cfg: Mapping, friction: FrictionTable) -> xr.Dataset:
    st = fe_cfg["stability"]
    base = scene_mapping(fe_cfg, st["base"])
    angles, slopes = list(st["angles"]), list(st["slopes"])
    g = np.zeros((len(angles), len(slopes)))
    fr = np.zeros_like(g)
    for i, a in enumerate(angles):
        mp = deep_merge(base, {"contact": {"angle_deg": a}})
        p = SceneParams.from_mapping(
            {k: v for k, v in mp.items() if k in ("beam", "disc", "contact", "solver")}
        )
        sc = build_scene(p, friction)
        for j, s in enumerate(slopes):
            g[i, j], fr[i, j] = max_growth(sliding_eigenvalues(sc.system, sc.law, slope=s))
    # table slope at the base scene's disc speed, and transient cross-checks with a linear law of that slope
    p0 = SceneParams.from_mapping(
        {k: v for k, v in base.items() if k in ("beam", "disc", "contact", "solver")}
    )
    V = p0.disc.surface_speed
    cc = st.get("crosscheck", [])
    cc_eig, cc_tr = [], []
    for a, s in cc:
        mp = deep_merge(base, {"contact": {"angle_deg": a}})
        p = SceneParams.from_mapping(
            {k: v for k, v in mp.items() if k in ("beam", "disc", "contact", "solver")}
        )
        lin = FrictionTable.linear(friction(V) - s * V, s, 2.0 * V)
        sc = build_scene(p, lin)
        cc_eig.append(max_growth(sliding_eigenvalues(sc.system, sc.law))[0])
        cc_tr.append(transient_growth_rate(sc.system, sc.law, float(st.get("crosscheck_duration", 0.01))))
    ds = xr.Dataset(
        {
            "max_growth_rate": (
                ("contact_angle", "friction_slope"),
                g,
                {"units": "s-1", "long_name": "largest real part of the linearised eigenvalues"},
            ),
            "unstable_frequency": (
                ("contact_angle", "friction_slope"),
                fr,
                {"units": "Hz", "long_name": "frequency of the least stable eigenvalue"},
            ),
            "crosscheck_eigen_growth_rate": (
                "crosscheck",
                np.array(cc_eig, float),
                {"units": "s-1", "long_name": "eigenvalue growth rate at the cross-check point"},
            ),
            "crosscheck_transient_growth_rate": (
                "crosscheck",
                np.array(cc_tr, float),
                {"units": "s-1", "long_name": "growth rate fitted to an explicit transient"},
            ),
            "crosscheck_angle": (
                "crosscheck",
                np.array([c[0] for c in cc], float),
                {"units": "degree", "long_name": "cross-check contact angle"},
            ),
            "crosscheck_slope": (
                "crosscheck",
                np.array([c[1] for c in cc], float),
                {"units": "s mm-1", "long_name": "cross-check friction slope"},
            ),
            "table_slope_at_disc_speed": (
                (),
                friction.slope(V),
                {"units": "s mm-1", "long_name": "d mu / d v_r of the friction table at the disc speed"},
            ),
        },
        coords={
            "contact_angle": (
                "contact_angle",
                np.array(angles, float),
                {"units": "degree", "long_name": "contact angle"},
            ),
            "friction_slope": (
                "friction_slope",
                np.array(slopes, float),
                {"units": "s mm-1", "long_name": "d mu / d v_r"},
            ),
        },
    )
    k0 = int(np.argmin(np.abs(np.array(slopes) - friction.slope(V))))
    a0 = int(np.argmin(np.abs(np.array(angles))))
    ds["growth_rate_at_table_slope_angle0"] = (
        (),
        g[a0, k0],
        {"units": "s-1", "long_name": "growth rate at angle 0 and the slope nearest the table's"},
    )
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": "Stability of steady sliding (complex eigenvalues)",
            "model_interpretation": INTERPRETATION,
            "base_scene": st["base"],
            "method": (
                "linearisation about steady sliding, friction slope included; "
                "cross-check by explicit transients"
            ),
        }
    )
    return ds


def cross_scene_dataset(datasets: Mapping[str, xr.Dataset], pairs: Mapping[str, list]) -> xr.Dataset:
    """Ratios lhs/rhs of a metric between two scenes: pairs = {name: [lhs_scene, rhs_scene, variable]}."""
    ds = xr.Dataset()
    for name, (a, b, var) in pairs.items():
        va, vb = float(datasets[a][var]), float(datasets[b][var])
        ds[name] = ((), va / vb if vb != 0 else np.nan, {"units": "1", "long_name": f"{var} of {a} over {b}"})
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": "Beam-on-disc cross-scene ratios",
            "model_interpretation": INTERPRETATION,
            "method": "ratios of scalar metrics",
            "pairs": json.dumps(dict(pairs)),
        }
    )
    return ds
