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

from ..fe.beam import (
    cantilever_axial_frequencies,
    cantilever_bending_frequencies,
    modal_analysis,
    node_coordinates,
)
from ..fe.explicit import integrate, static_state
from ..fe.metrics import (
    leading_growth_rate,
    mode_amplitude,
    trajectory_metrics,
    trend_sign,
    window_envelope,
)
from ..fe.params import FrictionTable
from ..fe.reduced import contact_boundary, craig_bampton
from ..fe.scene import SceneParams, build_scene
from ..fe.stability import max_growth, sliding_eigenvalues, sliding_state, transient_growth
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

INTERPRETATION = (
    "2-D frame elements (axial bar + Euler-Bernoulli bending stiffness, Rayleigh rotary inertia rho*I), "
    "clamped "
    "left end, steel E=210 GPa rho=7850 kg/m3, 1 mm out-of-plane width (gravity-only normal load: contact "
    "pressure, frequencies and displacements independent of width, forces proportional to it); rigid disc, "
    "small-displacement contact at the free end on the lower face (h/2 below the axis, the paper's slave "
    "surface) or on the axis (reading), fixed normal/tangent; contact angle = tilt of the disc normal at the "
    "contact towards the clamp; mu(|v_r|) from the tabulated friction law with static limit mu(0) and exact "
    "stick; light stiffness-proportional damping beta (solver.stiffness_damping) so that the response "
    "converges in mesh and step; start from rest undeformed with gravity at t=0 (drop, as ABAQUS/Explicit) "
    "or from the gravity equilibrium in contact (static), per reading; node 1 = the free-end point named by "
    "contact.output_node; displacements from the initial position."
)

UNITS = {
    "max_horizontal_displacement": ("mm", "maximum horizontal displacement of node 1"),
    "min_horizontal_displacement": ("mm", "minimum horizontal displacement of node 1"),
    "max_abs_horizontal_displacement": ("mm", "largest absolute horizontal displacement of node 1"),
    "mean_horizontal_displacement": ("mm", "mean horizontal displacement of node 1 (second half)"),
    "abs_mean_horizontal_displacement": ("mm", "absolute mean horizontal displacement (second half)"),
    "horizontal_amplitude": ("mm", "half peak-to-peak horizontal displacement (second half)"),
    "max_vertical_displacement": ("mm", "maximum absolute vertical displacement of node 1"),
    "vertical_amplitude": ("mm", "half peak-to-peak vertical displacement (second half)"),
    "max_abs_horizontal_velocity": ("mm s-1", "maximum absolute horizontal velocity of node 1"),
    "max_abs_vertical_velocity": ("mm s-1", "maximum absolute vertical velocity of node 1"),
    "midspan_vertical_amplitude": ("mm", "half peak-to-peak vertical displacement of the mid-span node"),
    "midspan_max_abs_vertical_velocity": (
        "mm s-1",
        "maximum absolute vertical velocity of the mid-span node",
    ),
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
    "separation_burst_time": (
        "s",
        "start of the first separation burst (first 5 ms window separated >= half the run's largest share)",
    ),
    "horizontal_amplitude_growth_ratio": ("1", "last-window over second-window horizontal half peak-to-peak"),
    "horizontal_nearest_mode_ratio": ("1", "horizontal dominant frequency over nearest natural frequency"),
    "vertical_nearest_mode_ratio": ("1", "vertical dominant frequency over nearest natural frequency"),
    "disc_surface_speed": ("mm s-1", "disc surface speed at the contact"),
    "first_mode_growth_rate": (
        "s-1",
        "growth rate of the first contact-held mode's horizontal amplitude at node 1 (leading segment)",
    ),
    "first_mode_growth_end": ("s", "end of the leading segment the first-mode growth rate is fitted over"),
    "first_mode_growth_rate_linear": (
        "s-1",
        "linearised sliding system's growth rate of the first contact-held mode (eigen-analysis, mu'(V))",
    ),
    "first_mode_frequency": ("Hz", "first natural frequency with contact held"),
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


def job_config(
    fe_cfg: Mapping, *, scenes=(), reading: str | None = None, sections=()
) -> dict:
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


def contact_held_modes(scene, n_modes: int = 40) -> tuple[np.ndarray, np.ndarray]:
    """Natural frequencies [Hz] and mode shapes (free-DOF columns) of the beam with the contact held
    (bilateral normal constraint)."""
    s = scene.system
    if scene.law.method == "fixed_normal" or not np.any(s.c_n):
        return modal_analysis(s.K, s.M, n_modes)
    from ..fe.stability import _null

    Z = _null(s.c_n)
    freq, phi = modal_analysis(Z.T @ s.K @ Z, Z.T @ s.M @ Z, n_modes)
    return freq, Z @ phi


def _natural_frequencies(scene) -> np.ndarray:
    """Natural frequencies [Hz] of the beam with the contact held (bilateral normal constraint)."""
    return contact_held_modes(scene)[0]


def nodal_field(scene, q: np.ndarray, component: int) -> np.ndarray:
    """Per-node values of one DOF component (0 axial, 1 vertical, 2 rotation) of a free-DOF vector q;
    zero at constrained DOFs (the clamp, the held transverse motion of Section 10)."""
    full = np.zeros(3 * scene.beam.n_nodes)
    full[scene.beam.free] = q
    return full[component::3].copy()


#: recorded mid-span components: (name, DOF component), in the order of the recorded columns
MIDSPAN_COMPONENTS = (("horizontal", 0), ("vertical", 1))


def _midspan_dofs(scene) -> np.ndarray:
    """Indices (among the free DOFs) of the mid-span node's axial and vertical DOFs, in the order of
    MIDSPAN_COMPONENTS; -1 for a held DOF (its series is then zero)."""
    free = scene.beam.free
    node = scene.params.beam.n_elements // 2
    out = []
    for _, comp in MIDSPAN_COMPONENTS:
        dof = 3 * node + comp
        k = int(np.searchsorted(free, dof))
        out.append(k if k < free.size and free[k] == dof else -1)
    return np.array(out, dtype=np.int64)


def midspan_motion(scene, r, dofs: np.ndarray) -> dict:
    """Displacement (from the start) and velocity of the mid-span node, a node off the contact, per
    component: {'horizontal': (x, v), 'vertical': (y, v)}; zeros where that DOF is held."""
    out = {}
    col = 0
    for (name, _), k in zip(MIDSPAN_COMPONENTS, dofs, strict=True):
        if k < 0 or r.q_samples is None:
            out[name] = (np.zeros_like(r.t), np.zeros_like(r.t))
            continue
        q = r.q_samples[:, col]
        out[name] = (q - q[0], r.v_samples[:, col].copy())
        col += 1
    return out


#: demodulation window of the first-mode amplitude [s] (18 periods of the 366 Hz bending mode)
MODE_WINDOW = 0.05


def linear_growth_rate(scene, frequency: float, solver) -> float:
    """Re(lambda) [s-1] of the linearised sliding system's eigenvalue nearest ``frequency`` [Hz]: the
    mode's negative-damping growth rate from mu'(V) at the disc speed, with the scene's Rayleigh damping
    (stickslip.fe.stability; the closed form -N mu' a^2/2 - beta w^2/2 of the propped bending mode agrees
    with it to 1 %). Section 10 (normal force held, transverse motion held): the closed form for the first
    axial mode, whose tangential amplitude at the tip is sqrt(2/(rho A L)) at unit modal mass."""
    if scene.law.method == "fixed_normal":
        from ..fe import mechanics as mc

        b = scene.params.beam
        return (
            mc.negative_damping_growth_rate(
                scene.law.fixed_normal_force,
                scene.law.friction.slope(scene.law.disc_speed),
                mc.axial_mode_tip_amplitude(b.rho * b.area, b.length),
                2 * np.pi * frequency,
                solver.stiffness_damping,
            )
            - 0.5 * solver.mass_damping
        )
    lam = sliding_eigenvalues(
        scene.system,
        scene.law,
        mass_damping=solver.mass_damping,
        stiffness_damping=solver.stiffness_damping,
    )
    return float(lam[np.argmin(np.abs(np.abs(lam.imag) / (2 * np.pi) - frequency))].real)


def mode_growth(r, frequency: float) -> tuple[dict, tuple]:
    """Growth of node 1's horizontal amplitude at ``frequency`` [Hz] (any model's trajectory): metrics (the
    growth rate fitted to the leading segment, stickslip.fe.metrics, its end, the frequency) and the
    amplitude series (window centres [s], amplitudes [mm]) per MODE_WINDOW."""
    tc, amp = mode_amplitude(r.t, r.x - r.x[0], frequency, MODE_WINDOW)
    rate, end = leading_growth_rate(tc, amp)
    return {
        "first_mode_growth_rate": rate,
        "first_mode_growth_end": end,
        "first_mode_frequency": float(frequency),
    }, (tc, amp)


def first_mode_growth(scene, r, frequency: float, solver) -> tuple[dict, tuple]:
    """The first contact-held mode's growth at node 1 (mode_growth) and the linear estimate of its rate
    (linear_growth_rate)."""
    m, series = mode_growth(r, frequency)
    return {**m, "first_mode_growth_rate_linear": linear_growth_rate(scene, frequency, solver)}, series


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
    mid = _midspan_dofs(scene) if midspan and not reduced else np.zeros(0, np.int64)
    r = integrate(
        system,
        scene.law,
        duration or sp.t_end,
        safety_factor=float((reduced or {}).get("safety_factor", sp.safety_factor)),
        output_interval=sp.output_dt,
        initial_state=sp.initial_state,
        mass_damping=sp.mass_damping,
        stiffness_damping=sp.stiffness_damping,
        progress=progress,
        record_state=midspan and not reduced,
        record_dofs=mid[mid >= 0] if midspan and not reduced else None,
    )
    if midspan and not reduced:
        r.extra["midspan"] = midspan_motion(scene, r, mid)
        r.q_samples = r.v_samples = None  # only the mid-span series are kept
    nat = _natural_frequencies(scene)
    m = trajectory_metrics(r, nat)
    growth, r.extra["first_mode_amplitude"] = first_mode_growth(scene, r, nat[0], sp)
    m.update(growth)
    if "midspan" in r.extra:
        y, vy = r.extra["midspan"]["vertical"]
        half = r.t >= 0.5 * r.t[-1]
        m["midspan_vertical_amplitude"] = float(0.5 * (y[half].max() - y[half].min()))
        m["midspan_max_abs_vertical_velocity"] = float(np.abs(vy).max())
    m["disc_surface_speed"] = p.disc.surface_speed
    _, evx = window_envelope(r.t, r.vx)
    _, evy = window_envelope(r.t, r.vy)
    _, ex = window_envelope(r.t, r.x - r.x[0])
    m["horizontal_velocity_trend"] = trend_sign(evx)
    m["vertical_velocity_trend"] = trend_sign(evy)
    m["horizontal_displacement_trend"] = trend_sign(ex)
    return r, m, scene


def _binned(t: np.ndarray, y: np.ndarray, edges: np.ndarray):
    """Per-bin (min, max, mean) of y over time bins (empty bins -> NaN)."""
    idx = np.clip(np.searchsorted(edges, t, side="right") - 1, 0, edges.size - 2)
    nb = edges.size - 1
    cnt = np.bincount(idx, minlength=nb).astype(float)
    mean = np.bincount(idx, weights=y, minlength=nb) / np.where(cnt > 0, cnt, np.nan)
    lo = np.full(nb, np.inf)
    hi = np.full(nb, -np.inf)
    np.minimum.at(lo, idx, y)
    np.maximum.at(hi, idx, y)
    lo[cnt == 0] = np.nan
    hi[cnt == 0] = np.nan
    return lo, hi, mean


def detail_mask(t: np.ndarray, windows) -> np.ndarray:
    keep = np.zeros(t.size, bool)
    for a, b in windows:
        keep |= (t >= a) & (t <= b)
    return keep


def default_windows(duration: float, span: float = 0.005) -> list:
    """Full-resolution windows kept in the dataset: the start (drop / first stick) and the end."""
    span = min(span, duration / 2)
    return [[0.0, span], [duration - span, duration]]


SERIES = {
    # name: (ExplicitResult attribute or callable, units, long_name)
    "horizontal_displacement": ("mm", "horizontal displacement of node 1 from its initial position"),
    "vertical_displacement": ("mm", "vertical displacement of node 1 from its initial position"),
    "horizontal_velocity": ("mm s-1", "horizontal velocity of node 1"),
    "vertical_velocity": ("mm s-1", "vertical velocity of node 1"),
    "normal_force": ("N", "contact normal force"),
    "friction_force": ("N", "friction force on the beam along the disc velocity"),
    "slip_velocity": ("mm s-1", "beam minus disc tangential velocity at the contact point"),
    "midspan_horizontal_displacement": (
        "mm",
        "horizontal displacement of the mid-span node (off the contact) from its initial position",
    ),
    "midspan_horizontal_velocity": ("mm s-1", "horizontal velocity of the mid-span node (off the contact)"),
    "midspan_vertical_displacement": (
        "mm",
        "vertical displacement of the mid-span node (off the contact) from its initial position",
    ),
    "midspan_vertical_velocity": ("mm s-1", "vertical velocity of the mid-span node (off the contact)"),
}

#: series stored per time bin (min, max, mean) over the whole run
BINNED = (
    "horizontal_displacement",
    "vertical_displacement",
    "horizontal_velocity",
    "vertical_velocity",
    "midspan_horizontal_displacement",
    "midspan_horizontal_velocity",
    "midspan_vertical_displacement",
    "midspan_vertical_velocity",
    "normal_force",
)


def _series(r) -> dict:
    out = {
        "horizontal_displacement": r.x - r.x[0],
        "vertical_displacement": r.y - r.y[0],
        "horizontal_velocity": r.vx,
        "vertical_velocity": r.vy,
        "normal_force": r.normal_force,
        "friction_force": r.friction_force,
        "slip_velocity": r.slip_velocity,
    }
    zeros = (np.zeros_like(r.t), np.zeros_like(r.t))
    for comp in ("horizontal", "vertical"):
        x, v = r.extra.get("midspan", {}).get(comp, zeros)
        out[f"midspan_{comp}_displacement"] = x
        out[f"midspan_{comp}_velocity"] = v
    return out


def result_dataset(r, m: Mapping, *, windows=None, bin_width: float = 1e-4) -> xr.Dataset:
    """Trajectory -> dataset: full-resolution samples only inside ``windows`` (dimension ``time``), and
    per-bin min/max/mean plus stick/slip/separation fractions over the whole run (``bin_time``), so that
    a 1 s run at >= 20 samples per 12.9 kHz period is stored and drawn without aliasing. Scalars ``m``
    become scalar variables (units from UNITS)."""
    t = r.t
    windows = windows if windows is not None else default_windows(float(t[-1]))
    keep = detail_mask(t, windows)
    ser = _series(r)
    data: dict = {}
    for k, (u, ln) in SERIES.items():
        data[k] = ("time", ser[k][keep], {"units": u, "long_name": ln})
    data["contact_state"] = (
        "time",
        r.state[keep].astype("i1"),
        {
            "units": "1",
            "long_name": "contact state",
            "flag_values": np.array([0, 1, 2], "i1"),
            "flag_meanings": "separated stick slip",
        },
    )
    edges = np.arange(0.0, t[-1] + bin_width, bin_width)
    if edges.size < 2:
        edges = np.array([0.0, t[-1]])
    for k in BINNED:
        u, ln = SERIES[k]
        lo, hi, mean = _binned(t, ser[k], edges)
        data[f"{k}_min"] = ("bin_time", lo, {"units": u, "long_name": f"minimum per bin of the {ln}"})
        data[f"{k}_max"] = ("bin_time", hi, {"units": u, "long_name": f"maximum per bin of the {ln}"})
        data[f"{k}_mean"] = ("bin_time", mean, {"units": u, "long_name": f"mean per bin of the {ln}"})
    for code, name in enumerate(("separation", "stick", "slip")):
        _, _, frac = _binned(t, (r.state == code).astype(float), edges)
        data[f"{name}_fraction_per_bin"] = (
            "bin_time",
            frac,
            {"units": "1", "long_name": f"fraction of output samples in {name} per bin"},
        )
    tw, evx = window_envelope(t, r.vx)
    for k, y, u in (
        ("horizontal_velocity", r.vx, "mm s-1"),
        ("vertical_velocity", r.vy, "mm s-1"),
        ("horizontal_displacement", ser["horizontal_displacement"], "mm"),
        ("vertical_displacement", ser["vertical_displacement"], "mm"),
    ):
        data[f"{k}_envelope"] = (
            "window",
            window_envelope(t, y)[1],
            {"units": u, "long_name": f"half peak-to-peak {k.replace('_', ' ')} per window"},
        )
    if "first_mode_amplitude" in r.extra:
        tc, amp = r.extra["first_mode_amplitude"]
        data["first_mode_amplitude"] = (
            "mode_window",
            amp,
            {"units": "mm", "long_name": "horizontal amplitude of the first contact-held mode at node 1"},
        )
        mode_window_time = tc
    else:
        mode_window_time = np.zeros(0)
    data["detail_windows"] = (
        ("detail_window", "bound"),
        np.array(windows, float),
        {"units": "s", "long_name": "start and end of the full-resolution windows"},
    )
    for k, v in m.items():
        u, ln = UNITS.get(k, ("1", k.replace("_", " ")))
        data[k] = ((), float(v), {"units": u, "long_name": ln})
    # One constructor call: assigning ~40 variables one by one re-aligns the whole dataset each time
    # (2.6 s of a 6 s FE reading job).
    return xr.Dataset(
        data,
        coords={
            "time": ("time", t[keep], {"units": "s", "long_name": "time (full-resolution windows only)"}),
            "bin_time": (
                "bin_time",
                0.5 * (edges[:-1] + edges[1:]),
                {"units": "s", "long_name": "bin centre"},
            ),
            "window_time": ("window", tw, {"units": "s", "long_name": "window centre time"}),
            "mode_window_time": (
                "mode_window",
                mode_window_time,
                {"units": "s", "long_name": "centre of the first-mode demodulation window"},
            ),
        },
    )


#: modes whose frequency and shape a scene dataset keeps
N_SHAPE_MODES = 10


def shape_variables(scene, q_static: np.ndarray) -> dict:
    """Along the beam (``node_position``): the static deflection in contact and the first modes with the
    contact held (shapes scaled so that their largest nodal displacement is +1), for
    the paper's Figs. 22 and 31 (mode shape, deflected beam)."""
    freq, phi = contact_held_modes(scene, N_SHAPE_MODES)
    x = node_coordinates(scene.params.beam.length, scene.params.beam.n_elements)
    shapes = {
        c: np.array([nodal_field(scene, phi[:, k], i) for k in range(freq.size)])
        for c, i in (("horizontal", 0), ("vertical", 1))
    }
    scale = np.maximum(np.abs(shapes["horizontal"]).max(axis=1), np.abs(shapes["vertical"]).max(axis=1))
    both = np.concatenate([shapes["horizontal"], shapes["vertical"]], axis=1)
    sign = np.sign(both[np.arange(freq.size), np.abs(both).argmax(axis=1)])
    pos = {"units": "mm", "long_name": "position of the node along the beam from the clamp"}
    out = {
        "node_position": ("node_position", x, pos),
        "natural_frequency": (
            "mode",
            freq,
            {"units": "Hz", "long_name": "natural frequencies with contact held"},
        ),
    }
    for c in ("horizontal", "vertical"):
        out[f"static_deflection_{c}"] = (
            "node_position",
            nodal_field(scene, q_static, 0 if c == "horizontal" else 1),
            {
                "units": "mm",
                "long_name": f"{c} displacement of the beam axis in the static equilibrium in contact",
            },
        )
        out[f"mode_shape_{c}"] = (
            ("mode", "node_position"),
            shapes[c] * (sign / np.where(scale > 0, scale, 1.0))[:, None],
            {"units": "1", "long_name": f"{c} component of the mode shape with contact held (largest = 1)"},
        )
    return out


def scene_dataset(mapping: Mapping, friction: FrictionTable, name: str = "", progress=None) -> xr.Dataset:
    """Pure build of one scene's dataset from its merged config mapping (the ensemble contract:
    ``build(mapping) -> xr.Dataset``). ``mapping['output']`` may give ``windows`` (list of [t0, t1] s)
    and ``bin_width`` [s]; ``progress(done, total)`` sees the time steps (``run_scene``)."""
    r, m, scene = run_scene(mapping, friction, midspan=True, progress=progress)
    out = dict(mapping.get("output", {}) or {})
    ds = result_dataset(r, m, windows=out.get("windows"), bin_width=float(out.get("bin_width", 1e-4)))
    ds = ds.assign(shape_variables(scene, r.q_static))
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": f"Beam on rotating rigid disc, scene {name}".strip(),
            "scene": name,
            "parameters": json.dumps(
                {
                    k: dataclasses.asdict(getattr(scene.params, k))
                    for k in ("beam", "disc", "contact", "solver")
                }
            ),
            "model_interpretation": INTERPRETATION,
            "method": (
                f"explicit central difference (compiled kernel), {scene.law.method} contact, dt={r.dt:.6g} s "
                f"(stable limit {r.dt_crit:.6g} s)"
            ),
            "diverged": int(r.extra.get("diverged", False)),
        }
    )
    return ds


FIT_LABEL = (
    "FIT, not the stated setup: the tip rests on a soft support (penalty contact) whose stiffness the closed "
    "form stickslip.fe.mechanics.soft_support_for_corner_displacement sets so that the static contact-corner "
    "offset equals the paper's Fig. 21 centre; everything else as the base scene"
)


def setup_fit_mapping(fe_cfg: Mapping, base: str, centre: float) -> tuple[dict, float]:
    """(scene mapping, support stiffness [N mm-1]) of the tip-support fit to Fig. 21's centre [mm]."""
    from ..fe import mechanics as mc
    from ..fe.params import BeamParams

    mp = scene_mapping(fe_cfg, base)
    b = BeamParams.from_mapping(mp.get("beam", {}))
    q = mc.distributed_weight(b.rho, b.area, b.g)
    k = mc.soft_support_for_corner_displacement(abs(centre), q, b.length, b.E * b.inertia, b.thickness)
    return deep_merge(mp, {"contact": {"method": "penalty", "penalty_stiffness": k}}), k


def setup_fit_dataset(mapping: Mapping, friction: FrictionTable, stiffness: float) -> xr.Dataset:
    """The fitted setup's scene dataset, labelled as a fit."""
    ds = scene_dataset(mapping, friction, "setup_fit")
    ds["tip_support_stiffness"] = (
        (),
        stiffness,
        {"units": "N mm-1", "long_name": "fitted tip support stiffness"},
    )
    ds.attrs["title"] = "Beam on rotating rigid disc: FIT of the tip support to Fig. 21"
    ds.attrs["model_interpretation"] = FIT_LABEL + ". " + INTERPRETATION
    return ds


def halved_step(mapping: Mapping) -> dict:
    """The scene mapping with its explicit time step halved (safety factor x 0.5)."""
    sf = float((mapping.get("solver", {}) or {}).get("safety_factor", 0.9))
    return deep_merge(mapping, {"solver": {"safety_factor": HALF_STEP * sf}})


def _sweep_rows(fe_cfg: Mapping, sweep_name: str, friction: FrictionTable, half_step: bool = False):
    sw = fe_cfg["sweeps"][sweep_name]
    base = scene_mapping(fe_cfg, sw["base"])
    path = sw["parameter"].split(".")
    rows = []
    for val in sw["values"]:
        mp = copy.deepcopy(base)
        mp.setdefault(path[0], {})[path[1]] = val
        if "t_end" in sw:
            mp.setdefault("solver", {})["t_end"] = sw["t_end"]
        _, m, _ = run_scene(halved_step(mp) if half_step else mp, friction)
        rows.append(m)
    return base, rows


def sweep_half_step(fe_cfg: Mapping, sweep_name: str, friction: FrictionTable) -> dict:
    """Every sweep member's scalar metrics at half its time step, as arrays along the sweep."""
    _, rows = _sweep_rows(fe_cfg, sweep_name, friction, half_step=True)
    return {k: np.array([r[k] for r in rows], float) for k in rows[0] if np.isscalar(rows[0][k])}


def sweep_dataset(fe_cfg: Mapping, sweep_name: str, friction: FrictionTable) -> xr.Dataset:
    sw = fe_cfg["sweeps"][sweep_name]
    base, rows = _sweep_rows(fe_cfg, sweep_name, friction)
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


CONVERGENCE_QUANTITIES = (
    "horizontal_amplitude",
    "mean_horizontal_displacement",
    "dominant_frequency",
    "stick_fraction",
    "separation_fraction",
)


def convergence_dataset(fe_cfg: Mapping, friction: FrictionTable) -> xr.Dataset:
    """Element count x time-step (safety factor) study of the base scene, plus the modal errors of the beam
    against the closed-form cantilever. For each quantity, the largest relative deviation from the finest
    run (most elements, smallest step) over the runs with at least the second-finest mesh is a scalar
    ``<quantity>_max_deviation`` (fractions: absolute deviation)."""
    cv = fe_cfg["convergence"]
    base = scene_mapping(fe_cfg, cv["base"])
    n_el = list(cv["n_elements"])
    sfs = list(cv.get("safety_factors", [base.get("solver", {}).get("safety_factor", 0.9)]))
    vals = {q: np.zeros((len(n_el), len(sfs))) for q in CONVERGENCE_QUANTITIES}
    dt = np.zeros((len(n_el), len(sfs)))
    bend_err, ax_err = [], []
    for i, n in enumerate(n_el):
        for j, sf in enumerate(sfs):
            mp = deep_merge(
                base, {"beam": {"n_elements": n}, "solver": {"t_end": cv["t_end"], "safety_factor": sf}}
            )
            r, m, scene = run_scene(mp, friction)
            for q in CONVERGENCE_QUANTITIES:
                vals[q][i, j] = m[q]
            dt[i, j] = r.dt
        from ..fe.beam import assemble_beam, classify_modes

        bp = scene.params.beam
        b = assemble_beam(bp)
        fr, phi = modal_analysis(b.K, b.M)
        ax = classify_modes(phi, b.free)
        bend_err.append(np.abs(fr[~ax][:3] / cantilever_bending_frequencies(bp, 3) - 1))
        ax_err.append(abs(fr[ax][0] / cantilever_axial_frequencies(bp, 1)[0] - 1))
    dims = ("n_elements", "safety_factor")
    ds = xr.Dataset(
        coords={
            "n_elements": (
                "n_elements",
                np.array(n_el),
                {"units": "1", "long_name": "number of beam elements"},
            ),
            "safety_factor": (
                "safety_factor",
                np.array(sfs, float),
                {"units": "1", "long_name": "time step over the stable limit"},
            ),
            "bending_mode": (
                "bending_mode",
                np.arange(1, 4),
                {"units": "1", "long_name": "cantilever bending mode"},
            ),
        }
    )
    for q in CONVERGENCE_QUANTITIES:
        u, ln = UNITS.get(q, ("1", q))
        ds[q] = (dims, vals[q], {"units": u, "long_name": ln})
        ref = vals[q][-1, -1]
        sub = vals[q][-2:, :]  # the two finest meshes, every step
        if q.endswith("_fraction"):
            dev = float(np.abs(sub - ref).max())
            what = "largest absolute deviation"
        else:
            dev = float(np.abs(sub / ref - 1).max()) if ref != 0 else float("nan")
            what = "largest relative deviation"
        ds[f"{q}_max_deviation"] = (
            (),
            dev,
            {"units": "1", "long_name": f"{what} of {q} on the two finest meshes from the finest run"},
        )
    ds["time_step"] = (dims, dt, {"units": "s", "long_name": "time step used"})
    ds["bending_frequency_error"] = (
        ("n_elements", "bending_mode"),
        np.array(bend_err),
        {"units": "1", "long_name": "relative error of the cantilever bending frequencies"},
    )
    ds["axial_frequency_error"] = (
        "n_elements",
        np.array(ax_err),
        {"units": "1", "long_name": "relative error of the first axial frequency"},
    )
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": "Beam-on-disc convergence in element count and time step",
            "model_interpretation": INTERPRETATION,
            "base_scene": cv["base"],
            "method": "explicit central difference per (n_elements, safety_factor)"
            "; modal errors vs closed form",
        }
    )
    return ds


def _scene_of(mapping: Mapping, friction: FrictionTable):
    p = SceneParams.from_mapping(
        {k: v for k, v in mapping.items() if k in ("beam", "disc", "contact", "solver")}
    )
    return build_scene(p, friction)


def stability_dataset(fe_cfg: Mapping, friction: FrictionTable) -> xr.Dataset:
    """Eigenvalue map over contact angle x friction slope, and explicit-transient cross-checks.

    Linearised about steady sliding with the sliding normal force (friction preload included) and the
    base scene's Rayleigh damping. Each cross-check runs the explicit integrator from the sliding state
    for ``crosscheck_e_folds`` e-foldings of the eigenvalue growth rate (at most
    ``crosscheck_max_t_end``) with a linear friction law of the cross-check slope."""
    st = fe_cfg["stability"]
    base = scene_mapping(fe_cfg, st["base"])
    angles, slopes = list(st["angles"]), list(st["slopes"])
    solver = base.get("solver", {})
    damp = {
        "mass_damping": float(solver.get("mass_damping", 0.0)),
        "stiffness_damping": float(solver.get("stiffness_damping", 0.0)),
    }
    g = np.zeros((len(angles), len(slopes)))
    fr = np.zeros_like(g)
    for i, a in enumerate(angles):
        sc = _scene_of(deep_merge(base, {"contact": {"angle_deg": a}}), friction)
        for j, s in enumerate(slopes):
            g[i, j], fr[i, j] = max_growth(sliding_eigenvalues(sc.system, sc.law, slope=s, **damp))
    V = _scene_of(base, friction).params.disc.surface_speed
    cc = st.get("crosscheck", [])
    rows: dict[str, list] = {
        k: [] for k in ("eig", "eig_f", "eig_static", "tr", "tr_f", "N_static", "N_slide")
    }
    for a, s in cc:
        lin = FrictionTable.linear(friction(V) - s * V, s, 2.0 * V)
        sc = _scene_of(deep_merge(base, {"contact": {"angle_deg": a}}), lin)
        ge, fe = max_growth(sliding_eigenvalues(sc.system, sc.law, **damp))
        rows["eig"].append(ge)
        rows["eig_f"].append(fe)
        rows["eig_static"].append(
            max_growth(sliding_eigenvalues(sc.system, sc.law, normal_force="static", **damp))[0]
        )
        rows["N_static"].append(static_state(sc.system, sc.law)[1])
        rows["N_slide"].append(sliding_state(sc.system, sc.law)[1])
        dur = min(float(st.get("crosscheck_max_t_end", 0.05)), float(st.get("crosscheck_e_folds", 8)) / ge)
        gt, ft = transient_growth(sc.system, sc.law, dur, **damp) if ge > 0 else (np.nan, np.nan)
        rows["tr"].append(gt)
        rows["tr_f"].append(ft)
    eig, tr = np.array(rows["eig"], float), np.array(rows["tr"], float)
    rel = np.abs(tr / eig - 1)

    def cc_var(v, units, long_name):
        return ("crosscheck", np.array(v, float), {"units": units, "long_name": long_name})

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
            "crosscheck_eigen_growth_rate": cc_var(
                eig, "s-1", "eigenvalue growth rate (sliding normal force)"
            ),
            "crosscheck_eigen_growth_rate_static_normal": cc_var(
                rows["eig_static"],
                "s-1",
                "eigenvalue growth rate with the static normal force (old analysis)",
            ),
            "crosscheck_eigen_frequency": cc_var(
                rows["eig_f"], "Hz", "frequency of the least stable eigenvalue"
            ),
            "crosscheck_transient_growth_rate": cc_var(
                tr, "s-1", "growth rate fitted to an explicit transient"
            ),
            "crosscheck_transient_frequency": cc_var(
                rows["tr_f"], "Hz", "dominant frequency of the growing transient (the mode that grows)"
            ),
            "crosscheck_relative_difference": cc_var(rel, "1", "|transient / eigenvalue growth rate - 1|"),
            "crosscheck_static_normal_force": cc_var(
                rows["N_static"], "N", "static normal force (no friction)"
            ),
            "crosscheck_sliding_normal_force": cc_var(
                rows["N_slide"], "N", "normal force in steady sliding (friction preload included)"
            ),
            "crosscheck_angle": cc_var([c[0] for c in cc], "degree", "cross-check contact angle"),
            "crosscheck_slope": cc_var([c[1] for c in cc], "s mm-1", "cross-check friction slope"),
            "crosscheck_max_relative_difference": (
                (),
                float(np.nanmax(rel)) if rel.size else np.nan,
                {
                    "units": "1",
                    "long_name": "largest |transient / eigenvalue growth rate - 1| of the cross-checks",
                },
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
    ds["unstable_frequency_at_table_slope_angle0"] = (
        (),
        fr[a0, k0],
        {"units": "Hz", "long_name": "frequency of the least stable mode at angle 0 and the table's slope"},
    )
    ds.attrs.update(
        {
            "Conventions": "CF-1.10",
            "title": "Stability of steady sliding (complex eigenvalues)",
            "model_interpretation": INTERPRETATION,
            "base_scene": st["base"],
            "method": (
                "linearisation about steady sliding (sliding normal force, friction slope, Rayleigh "
                "damping); "
                "cross-check by explicit transients from the sliding state"
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
        ea, eb = datasets[a].get(f"{var}_ensemble"), datasets[b].get(f"{var}_ensemble")
        if ea is not None and eb is not None and ea.shape == eb.shape:  # member by member
            with np.errstate(divide="ignore", invalid="ignore"):
                ratio = np.where(eb.values != 0, ea.values / eb.values, np.nan)
            ds[f"{name}_ensemble"] = (
                ea.dims,
                ratio,
                {"units": "1", "long_name": f"{var} of {a} over {b}, per perturbation-ensemble member"},
            )
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
