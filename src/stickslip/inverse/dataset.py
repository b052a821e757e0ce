"""One figure's fit (or the joint one) as an xarray dataset, both families along ``family``.

The dataset is driven by tables: every variable is a row (name, dims, units, long name, getter, extra
attributes), and its getter reads the fitted problems through a ``_Context`` that computes each shared array
once. A new variable is a new row; nothing else changes.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import xarray as xr

from .conflicts import CONFLICT_NFEV
from .fit import laplace_sd
from .identify import PROFILE_THRESHOLD, combination_rows, flat_extent, on_ridge, parameter_ranges
from .problem import COMBINATION_UNITS, COMBINATIONS, PARAMS, SYMBOLS, UNITS
from .profile import PL_THRESHOLD, quantity_ranges
from .structure import fibre_extent, identifiable_in_structure

INTERPRETATION = (
    "FIT, not a replication: parameter sets of the model family under which the paper's reported numbers "
    "(claims table values; noise = each claim's reading precision) are reproduced jointly by the exact "
    "event-driven solver. The claims table (stated parameters) is unchanged by this study."
)

COMBINATION_KEYS = {
    "K/M": "K_over_M",
    "C/M": "C_over_M",
    "mu_s N/M": "mu_s_N_over_M",
    "sigma": "sigma",
    "v_p": "v_p",
}

IDENTIFIABILITY_METHOD = (
    "structure from the equations, what the data bound from the profile likelihood. (1) Structural "
    "(stickslip.inverse.structure, sympy): each phase the best fit's runs visit (stick, slip backward or "
    "forward, the plateau) is fixed by combinations derived from M x'' + C x' + K x = F divided by M: "
    "K/M, the slip damping (C - mu_s N sigma)/M and the slip equilibrium, the stick release position "
    "(mu_s N - C V_b)/K, beyond the plateau C/M, its equilibrium and its switching speed v_p. The "
    "structural dimension is the rank of their Jacobian with respect to the log free parameters, in exact"
    " rational arithmetic: the same on every CPU. identifiable_dimensions is that rank, capped by the "
    "number of reported numbers (m numbers fix at most m directions). A parameter or combination whose "
    "log row is off the Jacobian's row space is a range (best_fit NaN), its extent taken over the fibre "
    "(every set with the same motion within the bounds). (2) Profile likelihood (Raue et al., "
    "Bioinformatics 2009) of each quantity the structure leaves identifiable (a free parameter, K/M, C/M "
    "or mu_s N/M): fixed on a grid and chi-square re-minimised over the others, warm-started along the "
    f"grid; identifiable when its profile exceeds delta chi2 = {PL_THRESHOLD:.2f} (95 % pointwise, one "
    "parameter) on both sides within the bounds, else a range, open where it stays within the threshold "
    "to a bound. No quantity whose interval spans more than a decade is called identifiable. A profile "
    "point deeper than the fit restarts the fit (least squares to convergence) and, if the fit drops by "
    "more than a quarter of the threshold, the profiles (at most 3 rounds). The straight-line chi-square "
    f"profiles (delta chi2 = {PROFILE_THRESHOLD:g}, stickslip.inverse.identify) are kept as a diagnostic"
)
CONFLICT_METHOD = (
    "subsets of the figure's reported numbers by increasing size up to conflict_search_max_size; a subset "
    "conflicts when the best fit to it alone (least squares, "
    f"at most {CONFLICT_NFEV} iterations, from the best witness) leaves a residual above 1; minimal: no "
    "conflicting proper subset (stickslip.inverse.conflicts)"
)


def _pad(values: np.ndarray, free: tuple, fill=np.nan) -> np.ndarray:
    out = np.full(len(PARAMS), fill, dtype=float)
    for i, p in enumerate(free):
        out[PARAMS.index(p)] = values[i]
    return out


@dataclass
class _Analysis:
    """The per-family numbers of one problem the datasets and tables are made of."""

    fit_point: np.ndarray
    lower: np.ndarray
    upper: np.ndarray
    ridge: np.ndarray
    """Not identifiable: reported as the range lower..upper, never as a point."""
    combo_point: dict
    combo_lower: dict
    combo_upper: dict
    dims: float
    opens: dict = field(default_factory=dict)
    """Name (free parameter or combination) -> (open below, open above): the range reaches the bounds."""
    combo_ridge: dict = field(default_factory=dict)
    note: str = ""
    """Why the count is below the structural dimension (fewer reported numbers)."""


def analyse(r: dict) -> _Analysis:
    """Ranges of the parameters and combinations of one fitted problem, from the straight-line profiles and
    the profile likelihood together (computed once, kept in ``r``)."""
    if "analysis" not in r:
        r["analysis"] = _analyse(r)
    return r["analysis"]


def _analyse(r: dict) -> _Analysis:
    p, fit, ident, pid = r["problem"], r["fit"], r["identification"], r.get("profile")
    v = np.asarray(fit.free_values, dtype=float)
    combos = p.combinations(v)
    if ident is None:
        nan = np.full(len(p.free), np.nan)
        return _Analysis(v, nan, nan, np.zeros(len(p.free), bool), combos, {}, {}, np.nan)
    lower, upper = parameter_ranges(p, v, ident)
    ridge = on_ridge(lower, upper)
    rows = combination_rows(p)
    ext = flat_extent(p, v, ident, np.array(list(rows.values()))) if rows else np.zeros((0, 2))
    c_lo = {n: combos[n] * 10.0 ** e[0] for n, e in zip(rows, ext) if n in combos}
    c_hi = {n: combos[n] * 10.0 ** e[1] for n, e in zip(rows, ext) if n in combos}
    c_ridge = {n: bool(on_ridge(c_lo[n], c_hi[n])) for n in c_lo}
    opens = {}
    if pid is not None:
        eye = {q: row for q, row in zip(p.free, np.eye(len(p.free)))}
        combo_rows = {n: rows[n] for n in c_lo if len(COMBINATIONS[n]) > 1}
        ranges = quantity_ranges(p, v, pid, {**eye, **combo_rows})
        for i, q in enumerate(p.free):
            lower[i], upper[i] = min(lower[i], ranges[q].lower), max(upper[i], ranges[q].upper)
            ridge[i] = ridge[i] or _unidentified(ranges[q])
        for n in combo_rows:
            q = ranges[n]
            c_lo[n], c_hi[n] = min(c_lo[n], q.lower), max(c_hi[n], q.upper)
            c_ridge[n] = c_ridge[n] or _unidentified(q)
        opens = {n: (q.open_lower, q.open_upper) for n, q in ranges.items()}
        for n in c_lo:  # a one-parameter combination (sigma, v_p) is that parameter
            (q,) = COMBINATIONS[n] if len(COMBINATIONS[n]) == 1 else (None,)
            if q in p.free:
                i = p.free.index(q)
                c_lo[n], c_hi[n], c_ridge[n], opens[n] = lower[i], upper[i], bool(ridge[i]), opens[q]
    # no quantity the equations leave free is a point: its range covers at least the fibre of the fit
    _fibre_ranges(r, v, lower, upper, c_lo, c_hi)
    # no quantity spanning more than a decade is called identifiable, and none the equations leave free
    ridge |= _wider_than_a_decade(lower, upper)
    c_ridge = {n: c_ridge[n] or bool(_wider_than_a_decade(c_lo[n], c_hi[n])) for n in c_ridge}
    ridge, c_ridge = _structural_ridges(r, ridge, c_ridge)
    dims, note = structural_count(r)
    return _Analysis(v, lower, upper, ridge, combos, c_lo, c_hi, dims, opens, c_ridge, note)


def structural_count(r: dict) -> tuple[float, str]:
    """(identifiable dimensions, note): the structural dimension derived from the equations (exact, the same
    on every CPU), capped by the number of reported numbers (m numbers fix at most m directions)."""
    s, m = float(r.get("structural_dimensions", np.nan)), len(r["problem"].observations)
    if not np.isfinite(s):
        return np.nan, ""
    if m < s:
        return float(m), f"at most {m} of the {int(s)} structural dimensions: {m} reported numbers"
    return s, ""


def _fibre_ranges(r: dict, v, lower, upper, c_lo: dict, c_hi: dict) -> None:
    """Widen (in place) the range of every free parameter and combination the equations leave free to its
    extent over the fit's fibre (``structure.fibre_extent``): where no profile traced it (the joint problem,
    a figure the settings do not profile), the straight-line ridges see only the fibre's straight part."""
    runs, p = r.get("structure") or (), r["problem"]
    if not runs:
        return
    free = tuple(p.free)
    rows = {**{q: row for q, row in zip(free, np.eye(len(free)))}, **combination_rows(p)}
    loose = {n: row for n, row in rows.items() if not identifiable_in_structure(runs, free, tuple(row))}
    if not loose:
        return
    u0 = np.log10(v)
    lo, hi = p.log_bounds
    pair = None
    if p.nonnegative_plateau and "plateau_speed" in free:
        pair = (free.index("sigma"), free.index("plateau_speed"))
    ext = 10.0 ** fibre_extent(runs, free, u0, np.array(list(loose.values())), lo, hi, pair)
    for (n, _), (e_lo, e_hi) in zip(loose.items(), ext):
        if n in free:
            i = free.index(n)
            lower[i], upper[i] = min(lower[i], e_lo), max(upper[i], e_hi)
        if n in c_lo:  # a combination, or a one-parameter one (sigma, v_p)
            c_lo[n], c_hi[n] = min(c_lo[n], e_lo), max(c_hi[n], e_hi)


def _structural_ridges(r: dict, ridge, c_ridge: dict):
    """Parameters and combinations the equations leave free (``identifiable_in_structure``) are ranges,
    whatever the profiles found: exact, so the same on every CPU."""
    runs, p = r.get("structure") or (), r["problem"]
    if not runs:
        return ridge, c_ridge
    free = tuple(p.free)
    ridge = np.array(
        [
            bool(flag) or not identifiable_in_structure(runs, free, tuple(np.eye(len(free))[i]))
            for i, flag in enumerate(ridge)
        ]
    )
    rows = combination_rows(p)
    c_ridge = {
        n: flag or (n in rows and not identifiable_in_structure(runs, free, tuple(rows[n])))
        for n, flag in c_ridge.items()
    }
    return ridge, c_ridge


#: A quantity whose interval spans more than this ratio is never called identifiable.
IDENTIFIABLE_MAX_RATIO = 10.0


def _wider_than_a_decade(lower, upper):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.asarray(upper, dtype=float) / np.asarray(lower, dtype=float) > IDENTIFIABLE_MAX_RATIO


def _unidentified(q) -> bool:
    """Profiled: its profile stays within the threshold to a bound; otherwise: its range reaches a bound."""
    return not q.identifiable if q.profiled else bool(q.open_lower or q.open_upper)


# -- the shared arrays, computed once per dataset ----------------------------------------------------------


@dataclass
class _Context:
    name: str
    results: dict
    settings: dict

    @cached_property
    def families(self) -> list:
        return list(self.results)

    @cached_property
    def first(self):
        return self.results[self.families[0]]["problem"]

    @cached_property
    def claims(self) -> list:
        return [o.claim for o in self.first.observations]

    @cached_property
    def analyses(self) -> dict:
        return {fam: analyse(self.results[fam]) for fam in self.families}

    @cached_property
    def n_samples(self) -> int:
        regions = [r["region"] for r in self.results.values() if r["region"] is not None]
        return max([len(reg.samples_free) for reg in regions] + [1])

    def each(self):
        """(index, family, fitted problem, analysis) of every family."""
        for f, fam in enumerate(self.families):
            yield f, fam, self.results[fam], self.analyses[fam]

    def scalar(self, fn) -> np.ndarray:
        return np.array([fn(r, a) for _, _, r, a in self.each()], dtype=float)

    @cached_property
    def parameters(self) -> dict:
        """Per-parameter arrays (family x parameter): PARAMETER_KINDS, ridge, spreads, samples."""
        nf, npar = len(self.families), len(PARAMS)
        out = {k: np.full((nf, npar), np.nan) for k in PARAMETER_KINDS}
        out["ridge"] = np.zeros((nf, npar), dtype=np.int8)
        out["sd"], out["laplace"] = np.full((nf, npar), np.nan), np.full((nf, npar), np.nan)
        out["samples"] = np.full((nf, self.n_samples, npar), np.nan)
        for f, _, r, a in self.each():
            p = r["problem"]
            out["fit_point"][f] = _pad(a.fit_point, p.free)
            out["best_fit"][f] = _pad(np.where(a.ridge, np.nan, a.fit_point), p.free)
            out["flat_lower"][f] = _pad(a.lower, p.free)
            out["flat_upper"][f] = _pad(a.upper, p.free)
            out["stated"][f] = _pad(p.stated_free, p.free)
            out["lower_bound"][f] = _pad(np.array([p.bounds[k][0] for k in p.free]), p.free)
            out["upper_bound"][f] = _pad(np.array([p.bounds[k][1] for k in p.free]), p.free)
            out["ridge"][f] = _pad(a.ridge.astype(float), p.free, fill=0).astype(np.int8)
            if np.all(np.isfinite(r["fit"].jacobian)):
                out["laplace"][f] = out["sd"][f] = _pad(laplace_sd(p, r["fit"].jacobian), p.free)
            if r["region"] is not None:
                for i, s in enumerate(r["region"].samples_free):
                    out["samples"][f, i] = _pad(s, p.free)
                out["sd"][f] = _pad(r["region"].sd_log10, p.free)
                out["laplace"][f] = _pad(r["region"].laplace_sd_log10, p.free)
        return out

    def open_flags(self, names) -> np.ndarray:
        """(family x name) 0 bounded, 1 open below, 2 open above, 3 both (see QuantityRange)."""
        out = np.zeros((len(self.families), len(names)), dtype=np.int8)
        for f, _, _, a in self.each():
            for j, n in enumerate(names):
                lo, hi = a.opens.get(n, (False, False))
                out[f, j] = int(lo) + 2 * int(hi)
        return out

    @cached_property
    def quantities(self) -> list:
        """Names of every quantity a profile likelihood was computed for, over the families."""
        names = [n for r in self.results.values() if r.get("profile") for n in r["profile"].profiles]
        return list(dict.fromkeys(names)) or [""]

    @cached_property
    def likelihood_profiles(self) -> dict:
        """(family x quantity x point) offsets and profiled chi-square, NaN-padded."""
        n = max(
            [
                len(pr.t)
                for r in self.results.values()
                if r.get("profile")
                for pr in r["profile"].profiles.values()
            ]
            + [1]
        )
        shape = (len(self.families), len(self.quantities), n)
        out = {"t": np.full(shape, np.nan), "chi2": np.full(shape, np.nan)}
        out["fixed"] = np.zeros(shape[:2], dtype=np.int8)
        for f, _, r, _ in self.each():
            pid = r.get("profile")
            for j, name in enumerate(self.quantities):
                pr = pid.profiles.get(name) if pid else None
                if pr is not None:
                    out["t"][f, j, : len(pr.t)], out["chi2"][f, j, : len(pr.t)] = pr.t, pr.chi2
                    out["fixed"][f, j] = int(name in pid.fixed)
        return out

    def combination(self, c: str) -> dict:
        """best / lower / upper / stated of one combination (per family)."""
        nf = len(self.families)
        point, lo, hi, stated = (np.full(nf, np.nan) for _ in range(4))
        for f, _, r, a in self.each():
            p = r["problem"]
            if c in a.combo_point:
                lo[f], hi[f] = a.combo_lower.get(c, np.nan), a.combo_upper.get(c, np.nan)
                moves = bool(a.combo_ridge.get(c, False)) or not np.isfinite(lo[f])
                point[f] = np.nan if moves else a.combo_point[c]
                stated[f] = p.combinations(p.stated_free).get(c, np.nan)
        return {"best_fit": point, "flat_lower": lo, "flat_upper": hi, "stated": stated}

    @cached_property
    def directions(self) -> dict:
        """Per-direction arrays (family x direction) of the straight-line profiles, and their vectors."""
        nf, npar = len(self.families), len(PARAMS)
        out = {k: np.full((nf, npar), np.nan) for k in DIRECTION_FIELDS}
        out["vector"] = np.full((nf, npar, npar), np.nan)
        for f, _, r, _ in self.each():
            ident, p = r["identification"], r["problem"]
            if ident is None:
                continue
            for i, pr in enumerate(ident.profiles):
                out["vector"][f, i] = _pad(pr.direction, p.free, fill=0.0)
                for k, get in DIRECTION_FIELDS.items():
                    out[k][f, i] = float(get(pr))
        return out

    @cached_property
    def residuals(self) -> dict:
        nf = len(self.families)
        out = {k: np.full((nf, len(self.claims)), np.nan) for k in ("fit", "stated", "loo")}
        for f, _, r, _ in self.each():
            out["fit"][f] = r["fit"].residuals
            out["stated"][f] = r["stated_residuals"]
            if r["loo"] is not None:
                out["loo"][f] = r["loo"]
        return out

    @cached_property
    def conflicts(self) -> dict:
        nf = len(self.families)
        n_conf = max([len(r["conflicts"].conflicts) for r in self.results.values() if r["conflicts"]] + [1])
        out = {
            "member": np.zeros((nf, n_conf, len(self.claims)), dtype=np.int8),
            "size": np.zeros((nf, n_conf)),
            "worst": np.full((nf, n_conf), np.nan),
            **{k: np.full(nf, np.nan) for k in ("max_size", "fitted", "count")},
        }
        for f, _, r, _ in self.each():
            search = r["conflicts"]
            if search is None:
                continue
            out["max_size"][f], out["fitted"][f] = search.max_size, search.subsets_fitted
            out["count"][f] = len(search.conflicts)
            for i, c in enumerate(search.conflicts):
                out["member"][f, i, list(c.members)] = 1
                out["size"][f, i], out["worst"][f, i] = len(c.members), c.worst
        return out

    @cached_property
    def chains(self) -> dict:
        nf = len(self.families)
        out = {
            "acceptance": np.full((nf, int(self.settings["walkers"])), np.nan),
            "tau": np.full((nf, len(PARAMS)), np.nan),
            "loglik": np.full((nf, self.n_samples), np.nan),
        }
        for f, _, r, _ in self.each():
            reg = r["region"]
            if reg is not None:
                out["acceptance"][f, : len(reg.acceptance)] = reg.acceptance
                out["tau"][f, : len(reg.autocorr_time)] = reg.autocorr_time
                out["loglik"][f, : len(reg.log_likelihood)] = reg.log_likelihood
        return out


# -- the tables --------------------------------------------------------------------------------------------

#: Per-parameter kinds: each is one variable per parameter, ``<kind>_<parameter>`` (one unit per variable).
PARAMETER_KINDS = {
    "best_fit": "best-fitting value where the numbers identify it (NaN where it is a range: see "
    "flat_lower/upper)",
    "fit_point": "one member of the best-fitting set (the one closest to the stated set); not an "
    "estimate where the parameter lies on a ridge",
    "flat_lower": "lowest value over the sets within the threshold in the bounds (identifiable: the profile-"
    "likelihood confidence interval; a range: its lower end)",
    "flat_upper": "highest value over the sets within the threshold in the bounds (identifiable: the profile-"
    "likelihood confidence interval; a range: its upper end)",
    "stated": "value as stated in the paper",
    "lower_bound": "lower physical bound (config inverse.bounds)",
    "upper_bound": "upper physical bound (config inverse.bounds)",
}

#: Per-combination kinds: ``<kind>_<combination key>``, in the combination's units.
COMBINATION_KINDS = {
    "best_fit": "{c} at the best fit (NaN where it moves along a ridge)",
    "flat_lower": "{c}: lowest over the flat set",
    "flat_upper": "{c}: highest over the flat set",
    "stated": "{c} as stated",
}

#: Fields of a straight-line profile stored per direction (getter on ``identify.Profile``).
DIRECTION_FIELDS = {
    "s": lambda pr: pr.singular_value,
    "kind": lambda pr: 0 if pr.structural else (1 if pr.unconstrained else 2),
    "tlo": lambda pr: pr.t_lower,
    "thi": lambda pr: pr.t_upper,
    "blo": lambda pr: pr.bound_lower,
    "bhi": lambda pr: pr.bound_upper,
    "rise": lambda pr: pr.rise,
    "ridge": lambda pr: pr.ridge,
}


@dataclass(frozen=True)
class Var:
    """One dataset variable: its name, dimensions, units, long name and how to get its values."""

    name: str
    dims: tuple
    units: str
    long_name: str
    get: Callable[[_Context], np.ndarray]
    attrs: dict = field(default_factory=dict)


FAM, FP, FC, FD = ("family",), ("family", "parameter"), ("family", "claim"), ("family", "direction")
FLAG01 = np.array([0, 1], dtype=np.int8)
OPEN_FLAGS = np.array([0, 1, 2, 3], dtype=np.int8)


def _parameter_vars() -> list[Var]:
    out = [
        Var(
            f"{kind}_{param}",
            FAM,
            UNITS[param],
            f"{SYMBOLS[param]}: {text}",
            lambda c, kind=kind, j=j: c.parameters[kind][:, j],
        )
        for kind, text in PARAMETER_KINDS.items()
        for j, param in enumerate(PARAMS)
    ]
    out += [
        Var(
            f"samples_{param}",
            ("family", "sample"),
            UNITS[param],
            f"{SYMBOLS[param]}: posterior samples (emcee, after burn-in)",
            lambda c, j=j: c.parameters["samples"][:, :, j],
            {"comment": "each sample is the set closest to the stated one with its motion"},
        )
        for j, param in enumerate(PARAMS)
    ]
    return out


PARAMETER_SPREADS = [
    Var(
        "on_ridge",
        FP,
        "1",
        "parameter not identifiable (1): reported as the range flat_lower..flat_upper, never a point",
        lambda c: c.parameters["ridge"],
        {"flag_values": FLAG01, "flag_meanings": "pinned on_ridge"},
    ),
    Var(
        "posterior_sd_log10",
        FP,
        "1",
        "posterior spread of log10 parameter",
        lambda c: c.parameters["sd"],
        {
            "comment": "sampled if the chain is >= 50 autocorrelation times long, else the Laplace "
            "(Gauss-Newton) spread; in the identifiable directions only (a ridge's extent is "
            "flat_lower..flat_upper)"
        },
    ),
    Var("laplace_sd_log10", FP, "1", "Laplace spread of log10 parameter", lambda c: c.parameters["laplace"]),
    Var(
        "range_open",
        FP,
        "1",
        "side(s) where the parameter's range reaches its bound within the threshold (unbounded by the data)",
        lambda c: c.open_flags(PARAMS),
        {"flag_values": OPEN_FLAGS, "flag_meanings": "bounded open_below open_above open_both"},
    ),
]


def _combination_vars() -> list[Var]:
    return [
        Var(
            f"{kind}_{COMBINATION_KEYS[name]}",
            FAM,
            COMBINATION_UNITS[name],
            text.format(c=name),
            lambda c, kind=kind, name=name: c.combination(name)[kind],
        )
        for name in COMBINATIONS
        for kind, text in COMBINATION_KINDS.items()
    ]


def _combination_open_vars() -> list[Var]:
    return [
        Var(
            f"range_open_{COMBINATION_KEYS[name]}",
            FAM,
            "1",
            f"{name}: side(s) where its range reaches the bounds within the threshold",
            lambda c, name=name: c.open_flags([name])[:, 0],
            {"flag_values": OPEN_FLAGS, "flag_meanings": "bounded open_below open_above open_both"},
        )
        for name, combo in COMBINATIONS.items()
        if len(combo) > 1
    ]


FQ = ("family", "quantity")
LIKELIHOOD_PROFILES = [
    Var(
        "likelihood_profile_offset",
        (*FQ, "profile_point"),
        "1",
        "log10 change of the quantity from the best fit at each point of its profile likelihood",
        lambda c: c.likelihood_profiles["t"],
    ),
    Var(
        "likelihood_profile_chi_square",
        (*FQ, "profile_point"),
        "1",
        "chi-square re-minimised over the other parameters with the quantity fixed (inf: no set within the "
        "bounds; a point within the threshold stops at the first set found there)",
        lambda c: c.likelihood_profiles["chi2"],
        {"threshold_delta_chi2": PL_THRESHOLD, "confidence": "0.95 pointwise, one parameter"},
    ),
    Var(
        "likelihood_profile_fixed",
        FQ,
        "1",
        "quantity fixed at its best fit to count a flat dimension (1)",
        lambda c: c.likelihood_profiles["fixed"],
        {"flag_values": FLAG01, "flag_meanings": "profiled fixed"},
    ),
]


def _direction(key: str):
    return lambda c: c.directions[key]


DIRECTIONS = [
    Var(
        "direction_vector",
        ("family", "direction", "parameter"),
        "1",
        "unit direction in log10 of the free parameters",
        _direction("vector"),
    ),
    Var(
        "direction_singular_value",
        FD,
        "1",
        "singular value of the residual Jacobian (per log10 unit); 0: structural or unconstrained",
        _direction("s"),
    ),
    Var(
        "direction_kind",
        FD,
        "1",
        "how the direction was found",
        _direction("kind"),
        {
            "flag_values": np.array([0.0, 1.0, 2.0]),
            "flag_meanings": "structural unconstrained profiled",
            "comment": "structural: exactly the same motion; unconstrained: beyond the number of reported "
            "numbers; profiled: a singular direction of the Jacobian",
        },
    ),
    Var(
        "profile_t_lower",
        FD,
        "1",
        "lower end [log10 units] of the interval within the threshold",
        _direction("tlo"),
    ),
    Var(
        "profile_t_upper",
        FD,
        "1",
        "upper end [log10 units] of the interval within the threshold",
        _direction("thi"),
    ),
    Var(
        "profile_reaches_lower_bound",
        FD,
        "1",
        "within the threshold down to the parameter bounds (1) or not (0)",
        _direction("blo"),
    ),
    Var(
        "profile_reaches_upper_bound",
        FD,
        "1",
        "within the threshold up to the parameter bounds (1) or not (0)",
        _direction("bhi"),
    ),
    Var(
        "profile_rise",
        FD,
        "1",
        "largest chi-square rise above the profile's minimum within the interval",
        _direction("rise"),
    ),
    Var("direction_is_ridge", FD, "1", "ridge (1): not identifiable", _direction("ridge")),
]


def _loo_comment(c: _Context) -> str:
    method = c.settings["loo"] if c.name == "joint" else "linear"
    return (
        f"method: {method} (linear: r_i / (1 - h_ii) at the best fit; refit: the problem refitted without it)"
    )


RESIDUALS = [
    Var(
        "residual",
        FC,
        "1",
        "(measured - reported) / reading precision at the best fit",
        lambda c: c.residuals["fit"],
    ),
    Var(
        "residual_stated",
        FC,
        "1",
        "(measured - reported) / reading precision with the stated parameters",
        lambda c: c.residuals["stated"],
    ),
    Var(
        "loo_residual",
        FC,
        "1",
        "leave-one-out residual (number left out of the fit)",
        lambda c: c.residuals["loo"],
        {"comment": _loo_comment},
    ),
]

CONFLICTS = [
    Var(
        "conflict_member",
        ("family", "conflict", "claim"),
        "1",
        "claim belongs to the minimal conflicting subset (1)",
        lambda c: c.conflicts["member"],
        {"comment": CONFLICT_METHOD},
    ),
    Var(
        "conflict_size",
        ("family", "conflict"),
        "1",
        "numbers in the minimal conflicting subset (0: no subset)",
        lambda c: c.conflicts["size"],
    ),
    Var(
        "conflict_worst_residual",
        ("family", "conflict"),
        "1",
        "smallest worst |residual| any fit to the subset alone reached (> 1)",
        lambda c: c.conflicts["worst"],
    ),
    Var(
        "conflict_search_max_size",
        FAM,
        "1",
        "largest subset size searched (NaN: not searched, the fit is consistent)",
        lambda c: c.conflicts["max_size"],
    ),
    Var(
        "conflict_subsets_fitted",
        FAM,
        "1",
        "subsets fitted alone (the others had a witness or held a conflict)",
        lambda c: c.conflicts["fitted"],
    ),
    Var("conflict_count", FAM, "1", "minimal conflicting subsets found", lambda c: c.conflicts["count"]),
]


def _per_family(fn, dtype=None):
    """Getter of a per-family scalar ``fn(fitted problem, analysis)``."""
    if dtype is None:
        return lambda c: c.scalar(fn)
    return lambda c: c.scalar(fn).astype(dtype)


def _region(fn):
    return _per_family(lambda r, a: fn(r["region"]) if r["region"] else np.nan)


PER_FAMILY = [
    Var(
        "worst_residual",
        FAM,
        "1",
        "largest |residual| at the best fit",
        _per_family(lambda r, a: r["fit"].worst),
    ),
    Var(
        "chi_square",
        FAM,
        "1",
        "sum of squared residuals at the best fit",
        _per_family(lambda r, a: r["fit"].chi2),
    ),
    Var(
        "consistent",
        FAM,
        "1",
        "verdict",
        _per_family(lambda r, a: r["fit"].consistent, np.int8),
        {"flag_values": FLAG01, "flag_meanings": "inconsistent consistent"},
    ),
    Var(
        "fit_source",
        FAM,
        "1",
        "where the best fit comes from",
        _per_family(lambda r, a: r["fit_source"] == "conflict search", np.int8),
        {"flag_values": FLAG01, "flag_meanings": "least_squares conflict_search_witness"},
    ),
    Var(
        "identifiable_dimensions",
        FAM,
        "1",
        "identifiable parameter directions: the structural dimension, at most the number of reported numbers",
        _per_family(lambda r, a: a.dims),
        {"comment": IDENTIFIABILITY_METHOD, "threshold_delta_chi2": PROFILE_THRESHOLD},
    ),
    Var(
        "structural_dimensions",
        FAM,
        "1",
        "rank of the derived combinations' log-Jacobian over the phases the best fit visits (exact)",
        _per_family(lambda r, a: r.get("structural_dimensions", np.nan)),
        {"comment": "stickslip.inverse.structure; the same on every CPU"},
    ),
    Var(
        "ridge_directions",
        FAM,
        "1",
        "flat directions (ridges) of the free parameters",
        _per_family(lambda r, a: len(r["problem"].free) - a.dims),
    ),
    Var(
        "motion_dimensions",
        FAM,
        "1",
        "directions that change the motion at all (rank of the combination map)",
        _per_family(lambda r, a: r["problem"].identifiable_basis().shape[1]),
    ),
    Var(
        "free_parameters",
        FAM,
        "1",
        "free parameters of the fit",
        _per_family(lambda r, a: len(r["problem"].free)),
    ),
    Var(
        "infeasible_fraction",
        FAM,
        "1",
        "fraction of sampler proposals that were infeasible",
        _region(lambda reg: reg.infeasible_fraction),
    ),
    Var(
        "forward_evaluations",
        FAM,
        "1",
        "forward-model evaluations",
        _per_family(lambda r, a: r["forward"].evaluations),
    ),
    Var(
        "chain_converged",
        FAM,
        "1",
        "chain >= 50 autocorrelation times (1) or not (0)",
        _region(lambda reg: float(reg.converged)),
    ),
    Var("chain_steps", FAM, "1", "emcee steps per walker", _region(lambda reg: reg.steps)),
    Var("cpu_time", FAM, "s", "process CPU time of the fit", _per_family(lambda r, a: r["cpu"])),
    Var(
        "acceptance_fraction",
        ("family", "walker"),
        "1",
        "emcee acceptance fraction per walker",
        lambda c: c.chains["acceptance"],
    ),
    Var(
        "autocorr_time",
        ("family", "coordinate"),
        "1",
        "integrated autocorrelation time [steps] per identifiable coordinate",
        lambda c: c.chains["tau"],
    ),
    Var(
        "sample_log_likelihood",
        ("family", "sample"),
        "1",
        "log-likelihood of each sample",
        lambda c: c.chains["loglik"],
    ),
]


def variables() -> list[Var]:
    """Every variable of a figure dataset, in the order they are written."""
    return (
        _parameter_vars()
        + PARAMETER_SPREADS
        + _combination_vars()
        + _combination_open_vars()
        + LIKELIHOOD_PROFILES
        + DIRECTIONS
        + RESIDUALS
        + CONFLICTS
        + PER_FAMILY
    )


def _coords(c: _Context) -> dict:
    obs = c.first.observations

    def text(values, long_name):
        return np.array(values, dtype=object), {"long_name": long_name}

    table = {
        "family": ("family", c.families, "model family"),
        "parameter": ("parameter", PARAMS, "parameter (BeltParams field)"),
        "parameter_units": ("parameter", [UNITS[p] for p in PARAMS], "units of the parameter"),
        "parameter_symbol": ("parameter", [SYMBOLS[p] for p in PARAMS], "symbol of the parameter"),
        "claim": ("claim", c.claims, "claim id (config/claims)"),
        "claim_unit": ("claim", [o.unit for o in obs], "unit of the reported number"),
        "claim_metric": ("claim", [o.metric for o in obs], "measured metric"),
        "claim_figure": ("claim", [o.figure for o in obs], "figure of the reported number"),
        "quantity": ("quantity", c.quantities, "quantity profiled (free parameter or combination)"),
    }
    return {key: (dim, *text(values, long_name)) for key, (dim, values, long_name) in table.items()}


def figure_dataset(name: str, results: dict[str, dict], settings: dict) -> xr.Dataset:
    """One figure (or the joint problem), both families along ``family``; every variable has units."""
    c = _Context(name, results, settings)
    data = {}
    for var in variables():
        attrs = {k: (v(c) if callable(v) else v) for k, v in var.attrs.items()}
        data[var.name] = (var.dims, var.get(c), {"units": var.units, "long_name": var.long_name, **attrs})
    ds = xr.Dataset(data, coords=_coords(c))
    ds.attrs.update(
        title=f"FIT (inverse study): {c.first.title}",
        interpretation=INTERPRETATION,
        figure=name,
        settings=json.dumps(settings, sort_keys=True),
        runs=json.dumps([{"name": r.name, "overrides": r.overrides} for r in c.first.runs], default=str),
        identifiability_method=IDENTIFIABILITY_METHOD,
        conflict_method=CONFLICT_METHOD,
    )
    return ds
