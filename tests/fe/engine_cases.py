"""The engine regression cases and their machine-independent summaries (used by
``test_engine_references.py``, its regeneration below, and ``benchmarks/check_engine_bits.py``).

Every case is a mapping of its settings (scene or strip parameters, start, time-step factor, damping, step
count) and :func:`run_case` builds and runs it. Floats of the mapping can be perturbed with
:func:`stickslip.ensemble.perturbed_mapping`: the regeneration runs each case at 1e-12 relative
perturbations and stores, next to the base run's summaries, their measured spread.

Regenerate (only when a result is meant to change; ~3 min on one core):
``.venv/bin/python tests/fe/engine_cases.py [CASE ...]``; print each case's largest deviation relative to
its tolerance on this machine: ``.venv/bin/python tests/fe/engine_cases.py --check``
"""

from __future__ import annotations

import copy
import functools
import json
import sys
from pathlib import Path

import numpy as np
import yaml

from stickslip.ensemble import perturbed_mapping
from stickslip.fe.continuum import build_continuum, integrate_continuum
from stickslip.fe.continuum import stable_time_step as continuum_stable_time_step
from stickslip.fe.explicit import integrate, stable_time_step
from stickslip.fe.params import BeamParams, ContactParams, DiscParams, FrictionTable, SceneParams
from stickslip.fe.reduced import contact_boundary, craig_bampton
from stickslip.fe.scene import build_scene
from stickslip.schema.fe import Fe
from stickslip.studies.fe_config import scene_mapping

ROOT = Path(__file__).resolve().parents[2]
REFERENCES = Path(__file__).with_name("engine_references.json")
FIG17 = FrictionTable.paper_fig17()
STICKY = FrictionTable((0.0, 0.6), (1e4, 0.9e4))  # friction far above what the strip can pull: it sticks
STEPS = 3000  # a few thousand steps: past the drop's first contact, with stick, slip and separation
SERIES = ("x", "y", "vx", "vy", "normal_force", "friction_force", "slip_velocity")
N_SAMPLES = 32  # values of each series at this many output samples, evenly spread over the run
STATES = ("separation", "stick", "slip")

#: Regeneration: 1e-12 relative perturbations of every float setting (stickslip.ensemble), these seeds.
RELATIVE = 1e-12
SEEDS = (1, 2, 3, 4)
#: A case is chaotic over its window when a series' spread exceeds this fraction of the series' scale
#: (a 1e-12 perturbation grown a millionfold); such a case is shortened (``steps``) until it is not.
CHAOTIC = 1e-6


# ------------------------------------------------------------------------------------------------ cases
@functools.cache
def _fe_config() -> Fe:
    return Fe.model_validate(yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"])


def _beam(scene, start, reduced=False, record=False, beta=None, alpha=0.0, dt_factor=None, steps=STEPS):
    fe = _fe_config()
    m = scene_mapping(fe, scene)
    return {
        "kind": "beam",
        "scene": {k: copy.deepcopy(m[k]) for k in ("beam", "disc", "contact", "solver")},
        "reduced": fe.reduced.model_dump(exclude_none=True) if reduced else None,
        "start": start,
        "record": record,
        "beta": beta,
        "alpha": alpha,
        "dt_factor": dt_factor or (0.5 if reduced else 0.9),
        "diverging": dt_factor is not None,
        "steps": steps,
    }


def _continuum(
    method, start, angle=0.0, record=False, dt_factor=None, speed=None, steps=STEPS, sticky=False,
    rotation="clockwise",
):  # fmt: skip
    disc = {"speed_rev_per_min": 15.2} if speed is None else {"surface_speed_mm_s": speed}
    return {
        "kind": "continuum",
        "beam": BeamParams().model_dump(),
        "disc": disc,
        "contact": {"method": method, "penalty_stiffness": 1000.0, "angle_deg": angle},
        "sticky": sticky,
        "rotation": rotation,
        "damping_beta": 5e-9,
        "start": start,
        "record": record,
        "dt_factor": dt_factor or 0.9,
        "diverging": dt_factor is not None,
        "output_interval": 2.5e-6,
        "steps": steps if not record else 300,
    }


def case_mappings() -> dict[str, dict]:
    """Every case's settings, by name (a fresh copy each call)."""
    return copy.deepcopy(_case_mappings())


@functools.cache
def _case_mappings() -> dict[str, dict]:
    cases = {
        f"beam_{model}_{scene}_{start}": _beam(scene, start, model == "reduced")
        for model in ("full", "reduced")
        for scene in (
            "section9_kinematic_15p2rpm",
            "section11_penalty_15p2rpm",
            "section10_fixed_normal_0p5mm_s",
        )  # fmt: skip
        for start in ("drop", "static")
    }
    cases |= {
        "beam_full_kinematic_30deg_drop_recorded": _beam("section12_angle30_15p2rpm", "drop", record=True),
        "beam_reduced_penalty_static_recorded": _beam("section11_penalty_0p5mm_s", "static", reduced=True,
                                                      record=True),
        "beam_full_kinematic_mass_damping_only": _beam("section9_kinematic_0p5mm_s", "drop", beta=0.0,
                                                       alpha=2000.0),
        "beam_full_kinematic_diverging": _beam("section9_kinematic_0p5mm_s", "static", dt_factor=3.0),
        "beam_full_kinematic_0p5mm_s_static_long": _beam("section9_kinematic_0p5mm_s", "static",
                                                         steps=40_000),
        "continuum_kinematic_drop": _continuum("kinematic", "drop"),
        "continuum_kinematic_static": _continuum("kinematic", "static"),
        "continuum_penalty_drop": _continuum("penalty", "drop"),
        "continuum_penalty_static": _continuum("penalty", "static"),
        "continuum_kinematic_30deg_drop": _continuum("kinematic", "drop", angle=30.0),
        "continuum_kinematic_recorded": _continuum("kinematic", "drop", record=True),
        "continuum_penalty_diverging": _continuum("penalty", "static", dt_factor=2.5),
        "continuum_kinematic_0p5mm_s_static_long": _continuum("kinematic", "static", speed=0.5, steps=40_000),
        "continuum_kinematic_sticking": _continuum("kinematic", "static", speed=0.5, sticky=True,
                                                   rotation="counterclockwise"),
        # lifts off at step ~600 and slips at ~650; chaotic from step ~940 on (1e-12 perturbations grow past
        # 1e-6 of the scale there, the regeneration's verdict): compared over 800 steps, not 20 000
        "continuum_penalty_sticking_lifts_off": _continuum("penalty", "static", speed=0.5, sticky=True,
                                                           steps=800),
    }  # fmt: skip
    return cases


def run_mapping(c: dict):
    """Build the case's system from its mapping and run it (the same calls as the studies make)."""
    if c["kind"] == "beam":
        p = SceneParams.from_mapping(c["scene"])
        scene = build_scene(p, FIG17)
        system, law = scene.system, scene.law
        n_modal = 0
        if c["reduced"]:  # as stickslip.fe.run.integrate_scene does
            red, boundary = c["reduced"], contact_boundary(system)
            mask = (scene.beam.free % 3) == 0
            system, T = craig_bampton(system, boundary, red["n_bending_modes"], mask, red["n_axial_modes"])
            n_modal = T.shape[1] - boundary.size
        dt = c["dt_factor"] * stable_time_step(system, law)
        record = c["record"]
        r = integrate(
            system, law, c["steps"] * dt * (1 - 1e-9), dt=dt, output_interval=p.solver.output_dt,
            initial_state=c["start"], mass_damping=c["alpha"],
            stiffness_damping=p.solver.stiffness_damping if c["beta"] is None else c["beta"],
            record_state=record,
            record_dofs=np.array([system.n - 1, 1, 4]) if record and not c["reduced"] else None,
            blowup=1.0 if c["diverging"] else 1e6, chunk=700,
        )  # fmt: skip
        # The reduced model's first coordinates are fixed-interface mode amplitudes, whose signs (and, for
        # close modes, mixing) are the eigensolver's choice: only the boundary coordinates are physical.
        r.extra["first_physical_coordinate"] = n_modal
        return r
    s = build_continuum(
        BeamParams(**c["beam"]), DiscParams(**{**c["disc"], "direction": c["rotation"]}),
        ContactParams(**c["contact"]), STICKY if c["sticky"] else FIG17, nx=100, ny=1,
        damping_beta=c["damping_beta"],
    )  # fmt: skip
    dt = c["dt_factor"] * continuum_stable_time_step(s)
    return integrate_continuum(
        s, c["steps"] * dt * (1 - 1e-9), dt=dt, output_interval=c["output_interval"],
        initial_state=c["start"], record_state=c["record"], blowup=1.0 if c["diverging"] else 1e3, chunk=700,
    )  # fmt: skip


def float_fields(node, path: str = "") -> list[str]:
    """Dotted paths of every float setting of a case mapping (integers such as step counts stay exact): the
    fields its round-off ensemble perturbs."""
    if isinstance(node, dict):
        return [f for k, v in node.items() for f in float_fields(v, f"{path}.{k}" if path else str(k))]
    return [path] if isinstance(node, float) else []


def run_case(name: str, relative: float = 0.0, seed: int = 0):
    c = case_mappings()[name]
    if not relative:
        return run_mapping(c)
    return run_mapping(perturbed_mapping(c, relative, seed, run_id=name, fields=float_fields(c)))


# -------------------------------------------------------------------------------------------- summaries
GROUPS = {  # series of one physical quantity: round-off in one is relative to the largest of them
    "x": "displacement", "y": "displacement", "vx": "velocity", "vy": "velocity", "slip_velocity": "velocity",
    "normal_force": "force", "friction_force": "force",
}  # fmt: skip


def series_of(r) -> dict[str, np.ndarray]:
    """Every output series of a run, the recorded state samples as a few physical coordinates (first,
    middle, last)."""
    out = {name: np.asarray(getattr(r, name), float) for name in SERIES}
    first = r.extra.get("first_physical_coordinate", 0)
    for name in ("q_samples", "v_samples"):
        a = getattr(r, name)
        if a is not None:
            a = np.asarray(a, float).reshape(len(a), -1)
            for k in sorted({first, (first + a.shape[1]) // 2, a.shape[1] - 1}):
                out[f"{name}[{k}]"] = a[:, k]
    return out


def group_scales(series: dict[str, np.ndarray]) -> dict[str, float]:
    """Per series, the largest magnitude of any series of its physical quantity (a component that stays
    at round-off level, as y on a kinematic contact, is measured against the displacement's scale)."""
    group = {name: GROUPS.get(name, name.split("[")[0]) for name in series}
    top = {}
    for name, a in series.items():
        top[group[name]] = max(top.get(group[name], 0.0), float(np.abs(a).max()) if a.size else 0.0)
    return {name: top[group[name]] for name in series}


def sample_indices(n: int) -> np.ndarray:
    return np.unique(np.linspace(0, n - 1, N_SAMPLES).round().astype(int))


def summaries(r) -> dict:
    """Compact, machine-independent summary of a run: the step count, diverged flag, steps per contact state
    (whole run and second half), the time step, and per series its mean, standard deviation, minimum,
    maximum and values at ``N_SAMPLES`` output samples."""
    out = {
        "n_steps": int(r.n_steps),
        "diverged": bool(r.extra["diverged"]),
        "step_counts": [int(r.step_counts[k]) for k in STATES],
        "dt": float(r.dt),
        "series": {},
    }
    half = r.extra.get("second_half_counts")
    if half is not None:
        out["second_half_counts"] = [int(half[k]) for k in STATES]
    series = series_of(r)
    for (name, a), scale in zip(series.items(), group_scales(series).values(), strict=True):
        out["series"][name] = {
            "stats": [float(a.mean()), float(a.std()), float(a.min()), float(a.max())],
            "samples": a[sample_indices(a.size)].tolist(),
            "scale": scale,
        }
    return out


def spread(base: dict, members: list[dict]) -> dict:
    """The largest deviation of every summary value of the members from the base run's."""
    counts = [np.abs(np.subtract(m["step_counts"], base["step_counts"])) for m in members]
    out = {
        "step_counts": np.max(counts, 0),
        "dt": max(abs(m["dt"] - base["dt"]) for m in members),
        "series": {},
    }
    if "second_half_counts" in base:
        out["second_half_counts"] = np.max(
            [np.abs(np.subtract(m["second_half_counts"], base["second_half_counts"])) for m in members], 0
        )
    for name, b in base["series"].items():
        out["series"][name] = {
            key: np.max([np.abs(np.subtract(m["series"][name][key], b[key])) for m in members], 0).tolist()
            for key in ("stats", "samples")
        }
    out["step_counts"] = out["step_counts"].tolist()
    if "second_half_counts" in out:
        out["second_half_counts"] = out["second_half_counts"].tolist()
    return out


#: Tolerance of every summary value of a series: MULTIPLE x the largest measured spread of that series'
#: values (samples and statistics) + FLOOR_ULPS x eps x n_steps x the scale of its physical quantity.
#: Another CPU or BLAS changes the inputs and each step's result in their last bits; over a run this
#: round-off moves the outputs by as much as the ensemble's 1e-12 perturbations do (measured with other
#: OpenBLAS kernels and generic NumPy/numba code: up to ~3x the spread of single values, ~0.3x the series'
#: largest spread). Taking the series' largest spread rather than each value's own keeps a value that
#: happened to move little in a few members from getting a tolerance below round-off; the multiple covers
#: the maximum over a few members underestimating the worst member. The floor is the round-off a run of
#: n_steps steps can accumulate (eps per step, relative to the scale) times a safety factor; it matters
#: only where the perturbations move nothing (a constant force, an exact zero).
MULTIPLE = 10.0
FLOOR_ULPS = 4.0
EPS = float(np.finfo(float).eps)


def tolerances(reference: dict, spread_: dict) -> dict:
    """The tolerance of every summary value (same layout as the spread)."""
    n = max(reference["n_steps"], 1)
    out = {
        "step_counts": [MULTIPLE * s for s in spread_["step_counts"]],
        "dt": MULTIPLE * spread_["dt"] + FLOOR_ULPS * EPS * reference["dt"],
        "series": {},
    }
    if "second_half_counts" in spread_:
        out["second_half_counts"] = [MULTIPLE * s for s in spread_["second_half_counts"]]
    for name, sp in spread_["series"].items():
        tol = (
            MULTIPLE * max(*sp["stats"], *sp["samples"])
            + FLOOR_ULPS * EPS * n * reference["series"][name]["scale"]
        )
        out["series"][name] = {key: [tol] * len(sp[key]) for key in ("stats", "samples")}
    return out


def deviations(summary: dict, reference: dict, spread_: dict) -> list[tuple[str, float, float]]:
    """(what, |deviation|, tolerance) of every compared value of a run's summary from the reference."""
    tol = tolerances(reference, spread_)
    out = []
    for key in ("step_counts", "second_half_counts"):
        if key in reference:
            for state, a, b, t in zip(STATES, summary[key], reference[key], tol[key], strict=True):
                out.append((f"{key}.{state}", float(abs(a - b)), t))
    out.append(("dt", abs(summary["dt"] - reference["dt"]), tol["dt"]))
    for name, ref in reference["series"].items():
        for key in ("stats", "samples"):
            a, b = np.asarray(summary["series"][name][key]), np.asarray(ref[key])
            d = np.abs(a - b) if a.shape == b.shape else np.full(b.shape, np.inf)
            out += [(f"{name}.{key}[{i}]", float(d[i]), t) for i, t in enumerate(tol["series"][name][key])]
    return out


def chaotic_series(base_run, member_runs) -> dict[str, int]:
    """Per series, the first step (at an output sample) where a member leaves the base run by more than
    ``CHAOTIC`` of the series' scale (series that stay within it are left out)."""
    every = max(1, round(float(base_run.t[1] - base_run.t[0]) / base_run.dt)) if base_run.t.size > 1 else 1
    found = {}
    b = series_of(base_run)
    for (name, a), scale in zip(b.items(), group_scales(b).values(), strict=True):
        dev = np.max([np.abs(series_of(m)[name] - a) for m in member_runs], 0)
        over = np.flatnonzero(dev > CHAOTIC * scale)
        if over.size:
            found[name] = int(over[0]) * every
    return found


def regenerate(names=None) -> dict:
    cases = case_mappings()
    table = json.loads(REFERENCES.read_text()) if REFERENCES.exists() and names else {}
    for name in names or cases:
        base_run = run_case(name)
        member_runs = [run_case(name, RELATIVE, seed) for seed in SEEDS]
        base = summaries(base_run)
        members = [summaries(m) for m in member_runs]
        chaos = chaotic_series(base_run, member_runs)
        table[name] = {"reference": base, "spread": spread(base, members)}
        print(name, base["n_steps"], base["step_counts"], base["diverged"], "chaotic from step", chaos,
              file=sys.stderr)  # fmt: skip
        if chaos:
            print(f"  {name} is chaotic over its window: shorten it", file=sys.stderr)
    write_references(table)
    return table


def _round_up(node):
    """Spreads to two significant digits, rounded up (a measured spread, not a bit pattern)."""
    if isinstance(node, dict):
        return {k: _round_up(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_round_up(v) for v in node]
    if isinstance(node, float) and node > 0:
        e = 10.0 ** (np.floor(np.log10(node)) - 1)
        return float(f"{np.ceil(node / e) * e:.2g}")
    return node


def write_references(table: dict) -> None:
    """One line per case: its reference summary and (rounded up) spread."""
    lines = [
        f"{json.dumps(name)}: "
        + json.dumps({"reference": e["reference"], "spread": _round_up(e["spread"])}, sort_keys=True)
        for name, e in sorted(table.items())
    ]
    REFERENCES.write_text("{\n" + ",\n".join(lines) + "\n}\n")


def check() -> float:
    """Print, per case, the largest deviation from the references relative to its tolerance; return the
    largest over all cases (<= 1: the test passes)."""
    table = json.loads(REFERENCES.read_text())
    worst_all = 0.0
    for name in table:
        s = summaries(run_case(name))
        e = table[name]
        same = (s["n_steps"], s["diverged"]) == (e["reference"]["n_steps"], e["reference"]["diverged"])
        ratios = [(d / t if t > 0 else (0.0 if d == 0 else np.inf), what) for what, d, t in deviations(
            s, e["reference"], e["spread"])]  # fmt: skip
        ratio, what = max(ratios)
        worst_all = max(worst_all, ratio if same else np.inf)
        print(f"{name:55s} max deviation/tolerance {ratio:.3g} ({what}){'' if same else ' STEPS DIFFER'}")
    print(f"all cases: max deviation/tolerance {worst_all:.3g}")
    return worst_all


if __name__ == "__main__":  # regenerate the stored references (optionally only the cases named); --check
    if sys.argv[1:] == ["--check"]:
        sys.exit(0 if check() <= 1.0 else 1)
    regenerate(sys.argv[1:])
