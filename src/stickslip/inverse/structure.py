"""Structural identifiability, derived once from the equations (sympy): which parameter combinations a run's
motion depends on, and how many of them are independent. Exact, so the same on every CPU.

In the consistent reading friction is F = a sgn(v_r) + b v + kappa V_b with a = -mu_s N, b = mu_s N sigma,
kappa = -mu_s N sigma (``stickslip.model.friction``). Divided by M, each phase of the motion is fixed by:

* slip in direction s (s = -1: slower than the belt): x'' + (C - b)/M x' + K/M x = K/M x_e(s), so K/M, the
  slip damping (C - b)/M and the slip equilibrium x_e(s) = (a s + kappa V_b)/K;
* stick: x moves with the belt until the spring and damper need more than mu_s N, at the release position
  x_r = (|a| + (b + kappa) V_b - C V_b)/K = (mu_s N - C V_b)/K;
* beyond the plateau speed v_p (the ``plateau`` family): C/M, the constant force's equilibrium
  (a s + b s v_p + (b + kappa) V_b)/K and the switching speed v_p itself (the switch time depends on it).

Inequalities that decide a discrete outcome (whether the mass sticks at v_r = 0) add nothing: a small change
of the parameters leaves the outcome, and so the motion, unchanged.

The initial state and V_b are inputs, not parameters. A run's structural dimension is the generic rank of
the Jacobian, with respect to the logarithms of the free parameters, of the combinations of the phases it
visits: no parameter set can move along its null space without leaving every visited phase's equation
unchanged, and the data can bound at most that many directions. For Fig. 2 in the consistent reading
(stick, then backward slip) the four combinations K/M, (C - mu_s N sigma)/M, x_r and x_e(-1) have rank 3:
x_e(-1) - x_r = (C - mu_s N sigma) V_b / K.
"""

from __future__ import annotations

import functools

import numpy as np
import sympy as sp
from scipy.optimize import minimize

from .forward import build_model
from .problem import SYMBOLS as PARAMETER_SYMBOLS

#: The model's parameters as sympy symbols (BeltParams field names), all positive: the inverse study's names
#: and the belt speed, an input of every run.
SYMBOLS = {
    name: sp.Symbol(symbol, positive=True)
    for name, symbol in {**PARAMETER_SYMBOLS, "belt_velocity": "V_b"}.items()
}
#: Phases a run can visit: stick, slip backward (v < V_b) or forward, and slip beyond the plateau speed.
PHASES = ("stick", "slip_backward", "slip_forward", "plateau")


def consistent_law() -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(a, b, kappa) of the consistent reading, F = a sgn(v_r) + b v + kappa V_b
    (``stickslip.model.friction.friction_law``; ``tests/inverse/test_inverse_structure.py`` checks they
    agree)."""
    mu_n, sigma = SYMBOLS["mu_s"] * SYMBOLS["normal_force"], SYMBOLS["sigma"]
    return -mu_n, mu_n * sigma, -mu_n * sigma


def phase_combinations(phases) -> dict[str, sp.Expr]:
    """The combinations the visited ``phases`` depend on (consistent reading), by name, derived from the
    equation of motion M x'' + C x' + K x = F (``stickslip.model.equations``) divided by M: in each slip
    phase the coefficients of x' and x and the equilibrium, in stick the release position (where the
    force the belt must supply reaches the friction limit), beyond the plateau its switching speed too."""
    unknown = set(phases) - set(PHASES)
    if unknown:
        raise ValueError(f"phases: {sorted(unknown)} are not among {PHASES}")
    p = SYMBOLS
    m, k, c, vb, vp = p["mass"], p["stiffness"], p["damping"], p["belt_velocity"], p["plateau_speed"]
    a, b, kappa = consistent_law()
    x, v = sp.symbols("x v", real=True)

    def normalised(force):
        """(x' coefficient, x coefficient, equilibrium) of x'' = (F - C v - K x) / M, linear in x and v."""
        acc = sp.expand((force - c * v - k * x) / m)
        damping, stiffness = -sp.diff(acc, v), -sp.diff(acc, x)
        return sp.simplify(damping), sp.simplify(stiffness), sp.simplify(acc.subs({x: 0, v: 0}) / stiffness)

    out: dict[str, sp.Expr] = {}
    for phase, s in (("slip_backward", -1), ("slip_forward", 1)):
        if phase in phases:
            damping, stiffness, equilibrium = normalised(a * s + b * v + kappa * vb)
            out["K/M"], out["(C - mu_s N sigma)/M"], out[f"x_e({s:+d})"] = stiffness, damping, equilibrium
            # beyond v_p the law's v_r is held at s v_p: F = a s + b s v_p + (b + kappa) V_b
            if "plateau" in phases:
                damping, _, equilibrium = normalised(a * s + b * s * vp + (b + kappa) * vb)
                out["C/M"], out[f"x_p({s:+d})"] = damping, equilibrium
                out["v_p"] = vp  # the switch into the plateau happens at |v_r| = v_p
    if "stick" in phases:  # x = x0 + V_b t while K x + C V_b - (b + kappa) V_b <= |a|: released where equal
        (release,) = sp.solve(sp.Eq(k * x + c * vb - (b + kappa) * vb, -a), x)
        out["x_r"] = sp.simplify(release)
    return out


#: Exact rational points (unrelated primes) at which a symbolic Jacobian's rank is taken. At a point the rank
#: never exceeds the generic (symbolic) rank, and equals it off the zero set of the minors, a proper algebraic
#: subset; the larger of two unrelated points is the generic rank unless both lie on it.
#: ``tests/inverse/test_inverse_structure.py`` checks it against sympy's symbolic rank for every phase set.
RANK_POINTS = (
    dict(mass="7/5", stiffness="13/3", damping="11/7", mu_s="5/11", normal_force="17/2", sigma="3/13",
         plateau_speed="19/23", belt_velocity="29/31"),
    dict(mass="41/37", stiffness="53/7", damping="3/43", mu_s="47/59", normal_force="61/5", sigma="2/67",
         plateau_speed="71/13", belt_velocity="11/73"),
)  # fmt: skip


def generic_rank(rows) -> int:
    """Rank of a matrix of expressions in the parameters: exact (rational arithmetic, the same on every
    CPU), the largest of its ranks at ``RANK_POINTS``."""
    if not rows or not rows[0]:
        return 0
    matrix = sp.Matrix(rows)
    return max(
        int(matrix.subs({SYMBOLS[k]: sp.Rational(v) for k, v in point.items()}).rank())
        for point in RANK_POINTS
    )


def visited_phases(traj, plateau_speed: float = float("inf")) -> tuple:
    """The phases an exact trajectory visits (its switching record), and the plateau where |v_r| exceeds
    ``plateau_speed``."""
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


def _run_combinations(runs: tuple) -> list[tuple[sp.Expr, tuple]]:
    """(combination, names the run overrides) of every run of ``runs`` ((phases, fixed pairs, overridden
    names) per run), its inputs substituted as exact rationals."""
    out = []
    for phases, fixed, overridden in runs:
        subs = {SYMBOLS[name]: sp.Rational(str(value)) for name, value in fixed}
        out += [(sp.sympify(e).subs(subs), overridden) for e in phase_combinations(phases).values()]
    return out


@functools.cache
def _jacobian_rows(runs: tuple, free: tuple) -> list:
    """d(combinations)/d log(free) of every run, stacked; a parameter a run overrides (a sweep's value) is an
    input there, its column zero."""
    return [
        [0 if q in overridden else SYMBOLS[q] * sp.diff(e, SYMBOLS[q]) for q in free]
        for e, overridden in _run_combinations(runs)
    ]


@functools.cache
def runs_rank(runs: tuple, free: tuple) -> int:
    """Generic rank over the runs of one problem (``_jacobian_rows``)."""
    rows = _jacobian_rows(runs, free)
    return generic_rank(rows) if rows and free else 0


@functools.cache
def identifiable_in_structure(runs: tuple, free: tuple, exponents: tuple) -> bool:
    """Whether a monomial quantity (``exponents``: its log10 row over the free parameters) is fixed by the
    combinations the runs depend on: its row lies in their Jacobian's row space. If not, parameter sets with
    the same motion give it different values, so it is a range, never a point, whatever an optimiser finds."""
    rows = _jacobian_rows(runs, free)
    if not rows:
        return not any(exponents)
    with_row = list(rows) + [[sp.Rational(str(x)) for x in exponents]]
    return generic_rank(with_row) == runs_rank(runs, free)


def problem_structure(problem, free_values) -> tuple[int, tuple, tuple]:
    """(structural dimension, the phases each run visits, the runs' structure for
    ``identifiable_in_structure``) of an inverse problem at a parameter set: each run solved once by the
    forward model's own solver, its visited phases read off its switching record."""
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


# -- the fibre: every parameter set with the same motion ---------------------------------------------------


@functools.cache
def independent_combinations(runs: tuple, free: tuple) -> tuple:
    """A maximal set of the runs' combinations with independent log-Jacobian rows (exact generic rank): the
    equations that pin the fibre, as many as the structural dimension."""
    chosen, rows = [], []
    expressions = dict.fromkeys(e for e, _ in _run_combinations(runs) if e.free_symbols)
    for e in expressions:
        row = [SYMBOLS[q] * sp.diff(e, SYMBOLS[q]) for q in free]
        if generic_rank(rows + [row]) > len(rows):
            chosen.append(e)
            rows.append(row)
    return tuple(chosen)


@functools.cache
def _fibre_functions(runs: tuple, free: tuple):
    """(h, dh/du) of the independent combinations as numpy functions of u = log10 of the free values."""
    exprs = independent_combinations(runs, free)
    syms = [SYMBOLS[q] for q in free]
    h = sp.lambdify([syms], list(exprs), "numpy")
    jac = sp.lambdify([syms], [[sp.diff(e, s) for s in syms] for e in exprs], "numpy")
    ln10 = float(np.log(10.0))

    def values(u):
        return np.array(h(list(10.0 ** np.asarray(u, dtype=float))), dtype=float).reshape(-1)

    def jacobian(u):
        x = 10.0 ** np.asarray(u, dtype=float)
        return np.array(jac(list(x)), dtype=float).reshape(len(exprs), len(free)) * x * ln10

    return values, jacobian


#: A set is on the fibre when every independent combination matches to this relative tolerance.
FIBRE_TOL = 1e-8


def fibre_extent(runs: tuple, free: tuple, u0, rows, lower, upper, pair=None, starts=()):
    """(lowest, highest) of each ``row . u`` over the fibre through ``u0`` within the bounds: the sets u
    (log10 of the free values, ``lower <= u <= upper``, and ``u[i] + u[j] <= 0`` for ``pair = (i, j)``) whose
    motion is that of u0, because every combination the runs depend on keeps its value.

    The fibre is curved in log coordinates (Fig. 2: sigma and mu_s N bend against C), so each extreme is a
    small constrained optimisation (SLSQP, exact Jacobians of the derived combinations) started from u0 and
    from ``starts`` (sets known to lie on the fibre, e.g. the corners of its straight part); only a result
    back on the fibre (``FIBRE_TOL``) within the bounds counts, so a range is never wider than the fibre,
    and at least the extent of the starts."""
    u0 = np.asarray(u0, dtype=float)
    rows = np.atleast_2d(np.asarray(rows, dtype=float))
    lower, upper = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
    base = rows @ u0
    out = np.column_stack([base, base])
    if not runs:
        return out
    values, jacobian = _fibre_functions(runs, free)
    h0 = values(u0)
    if h0.size == 0:
        return out
    scale = np.where(np.abs(h0) > 1e-12, np.abs(h0), 1.0)

    def on_fibre(u) -> bool:
        inside = np.all(u >= lower - 1e-9) and np.all(u <= upper + 1e-9)
        if pair is not None:
            inside = inside and u[pair[0]] + u[pair[1]] <= 1e-9
        return bool(inside and np.max(np.abs(values(u) - h0) / scale) <= FIBRE_TOL)

    constraints = [
        {
            "type": "eq",
            "fun": lambda u: (values(u) - h0) / scale,
            "jac": lambda u: jacobian(u) / scale[:, None],
        }
    ]
    if pair is not None:
        e = np.zeros(len(u0))
        e[list(pair)] = -1.0
        constraints.append({"type": "ineq", "fun": lambda u: float(e @ u), "jac": lambda u: e})
    known = [u0] + [np.asarray(s, dtype=float) for s in starts if on_fibre(np.asarray(s, dtype=float))]
    box = list(zip(lower, upper))
    for n, row in enumerate(rows):
        for col, sign in ((0, 1.0), (1, -1.0)):
            best = min(sign * (row @ u) for u in known)
            for start in known:
                res = minimize(
                    lambda u, c=sign * row: float(c @ u),
                    np.clip(start, lower, upper),
                    jac=lambda u, c=sign * row: c,
                    method="SLSQP",
                    bounds=box,
                    constraints=constraints,
                    options={"maxiter": 100, "ftol": 1e-10},
                )
                if on_fibre(res.x):
                    best = min(best, sign * float(row @ res.x))
            out[n, col] = sign * best
    return out
