"""Structural identifiability, derived once from the equations (sympy): which parameter combinations a run's
motion depends on, and how many of them are independent. Exact, so the same on every CPU.

In the consistent reading friction is F = a sgn(v_r) + b v + kappa V_b with a = -mu_s N, b = mu_s N sigma,
kappa = -mu_s N sigma (``stickslip.model.friction``). Divided by M, each phase of the motion is fixed by:

* slip in direction s (s = -1: slower than the belt): x'' + (C - b)/M x' + K/M x = K/M x_e(s), so K/M, the
  slip damping (C - b)/M and the slip equilibrium x_e(s) = (a s + kappa V_b)/K;
* stick: x moves with the belt until the spring and damper need more than mu_s N, at the release position
  x_r = (|a| + (b + kappa) V_b - C V_b)/K = (mu_s N - C V_b)/K;
* beyond the plateau speed v_p (the ``plateau`` family): C/M and the constant force's equilibrium
  (a s + b s v_p + (b + kappa) V_b)/K.

The initial state and V_b are inputs, not parameters. A run's structural dimension is the generic rank of
the Jacobian, with respect to the logarithms of the free parameters, of the combinations of the phases it
visits: no parameter set can move along its null space without leaving every visited phase's equation
unchanged, and the data can bound at most that many directions. For Fig. 2 in the consistent reading
(stick, then backward slip) the four combinations K/M, (C - mu_s N sigma)/M, x_r and x_e(-1) have rank 3:
x_e(-1) - x_r = (C - mu_s N sigma) V_b / K.
"""

from __future__ import annotations

import functools

import sympy as sp

#: The model's parameters as sympy symbols (BeltParams field names), all positive.
SYMBOLS = {
    name: sp.Symbol(symbol, positive=True)
    for name, symbol in (
        ("mass", "M"),
        ("stiffness", "K"),
        ("damping", "C"),
        ("mu_s", "mu_s"),
        ("normal_force", "N"),
        ("sigma", "sigma"),
        ("plateau_speed", "v_p"),
        ("belt_velocity", "V_b"),
    )
}
#: Phases a run can visit: stick, slip backward (v < V_b) or forward, and slip beyond the plateau speed.
PHASES = ("stick", "slip_backward", "slip_forward", "plateau")


def phase_combinations(phases) -> dict[str, sp.Expr]:
    """The combinations the visited ``phases`` depend on (consistent reading), by name."""
    unknown = set(phases) - set(PHASES)
    if unknown:
        raise ValueError(f"phases: {sorted(unknown)} are not among {PHASES}")
    p = SYMBOLS
    m, k, c, vb, vp = p["mass"], p["stiffness"], p["damping"], p["belt_velocity"], p["plateau_speed"]
    mu_n = p["mu_s"] * p["normal_force"]
    a, b, kappa = -mu_n, mu_n * p["sigma"], -mu_n * p["sigma"]
    out: dict[str, sp.Expr] = {}
    for phase, s in (("slip_backward", -1), ("slip_forward", 1)):
        if phase in phases:
            out["K/M"] = k / m
            out["(C - mu_s N sigma)/M"] = (c - b) / m
            out[f"x_e({s:+d})"] = (a * s + kappa * vb) / k
            if "plateau" in phases:
                out["C/M"] = c / m
                out[f"x_p({s:+d})"] = (a * s + b * s * vp + (b + kappa) * vb) / k
    if "stick" in phases:
        out["x_r"] = (-a + (b + kappa) * vb - c * vb) / k
    return out


@functools.cache
def structural_rank(phases: tuple, free: tuple, fixed: tuple = ()) -> int:
    """Generic rank of d(combinations)/d log(free parameters) for the visited ``phases``; ``fixed``: (name,
    value) pairs substituted first (inputs such as V_b, parameters a run fixes), as exact rationals."""
    combos = list(phase_combinations(phases).values())
    if not combos or not free:
        return 0
    subs = {SYMBOLS[name]: sp.Rational(str(value)) for name, value in fixed}
    rows = [[SYMBOLS[q] * sp.diff(e, SYMBOLS[q]) for q in free] for e in combos]
    return int(sp.Matrix(rows).subs(subs).rank(simplify=True))


def visited_phases(traj, plateau_speed: float = float("inf")) -> tuple:
    """The phases an exact trajectory visits (its switching record), and the plateau where |v_r| exceeds
    ``plateau_speed``."""
    import numpy as np

    found = set()
    segments = np.asarray(traj.segments if traj.segments is not None else [], dtype=float).reshape(-1, 3)
    for t0, t1, phase in segments:
        if phase == 0 and t1 > t0:
            found.add("stick")
        elif phase < 0:
            found.add("slip_backward")
        elif phase > 0:
            found.add("slip_forward")
    vr = np.asarray(traj.v, dtype=float) - np.asarray(traj.belt_velocity, dtype=float)
    if np.isfinite(plateau_speed) and np.any(np.abs(vr[np.isfinite(vr)]) > plateau_speed):
        found.add("plateau")
    return tuple(p for p in PHASES if p in found)


def _jacobian_rows(runs: tuple, free: tuple) -> list:
    """d(combinations)/d log(free) of every run, stacked: ``runs`` holds (phases, fixed pairs, overridden
    names) per run; a parameter a run overrides (a sweep's value) is an input there, its column zero."""
    rows = []
    for phases, fixed, overridden in runs:
        subs = {SYMBOLS[name]: sp.Rational(str(value)) for name, value in fixed}
        for e in phase_combinations(phases).values():
            row = [0 if q in overridden else SYMBOLS[q] * sp.diff(e, SYMBOLS[q]) for q in free]
            rows.append([sp.sympify(x).subs(subs) for x in row])
    return rows


@functools.cache
def runs_rank(runs: tuple, free: tuple) -> int:
    """Generic rank over the runs of one problem (``_jacobian_rows``)."""
    rows = _jacobian_rows(runs, free)
    return int(sp.Matrix(rows).rank(simplify=True)) if rows and free else 0


@functools.cache
def identifiable_in_structure(runs: tuple, free: tuple, exponents: tuple) -> bool:
    """Whether a monomial quantity (``exponents``: its log10 row over the free parameters) is fixed by the
    combinations the runs depend on: its row lies in their Jacobian's row space. If not, parameter sets with
    the same motion give it different values, so it is a range, never a point, whatever an optimiser finds."""
    rows = _jacobian_rows(runs, free)
    if not rows:
        return not any(exponents)
    with_row = rows + [[sp.Rational(str(x)) for x in exponents]]
    return sp.Matrix(with_row).rank(simplify=True) == runs_rank(runs, free)


def problem_structure(problem, free_values) -> tuple[int, tuple, tuple]:
    """(structural dimension, the phases each run visits, the runs' structure for
    ``identifiable_in_structure``) of an inverse problem at a parameter set: each run solved once by the
    forward model's own solver, its visited phases read off its switching record."""
    from .forward import build_model

    settings, per_run = problem.run_settings, []
    for run in problem.runs:
        params = problem.run_params(free_values, run)
        model, solver = build_model(params, problem.variant)
        traj = solver.solve(model, settings["t_end"])
        phases = visited_phases(traj, float(params.plateau_speed))
        inputs = [n for n in SYMBOLS if n not in problem.free or n in run.overrides]
        fixed = tuple((n, getattr(params, n)) for n in inputs if n != "plateau_speed" or "plateau" in phases)
        per_run.append((phases, fixed, tuple(sorted(set(run.overrides) & set(problem.free)))))
    runs = tuple(per_run)
    return runs_rank(runs, tuple(problem.free)), tuple(p for p, _, _ in per_run), runs
