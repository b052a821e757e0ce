"""One figure's fit (or the joint one) as an xarray dataset, both families along ``family``.

Each family's fit is a typed ``FamilyFit`` whose ``to_dataset()`` gives its own variables; a figure's
dataset concatenates them along ``family`` (an outer join pads the shorter ones). ``VARIABLES`` holds every
variable's CF attributes, in the order they are written.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import xarray as xr

from ..schema import Inverse
from .conflicts import CONFLICT_NFEV, ConflictSearch
from .fit import BestFit, Region, laplace_sd
from .forward import Forward
from .identify import (
    PROFILE_THRESHOLD,
    Identification,
    combination_rows,
    flat_extent,
    on_ridge,
    parameter_ranges,
    quantity_rows,
)
from .problem import COMBINATION_UNITS, COMBINATIONS, PARAMS, SYMBOLS, UNITS, Problem
from .profile import PL_THRESHOLD, ProfileIdentification, quantity_ranges
from .structure import fibre_extent, identifiable_in_structure

INTERPRETATION = (
    "FIT, not a replication: parameter sets of the model family under which the paper's reported numbers "
    "(claims table values; noise = each claim's reading precision) are reproduced jointly by the exact "
    "event-driven solver. The claims table (stated parameters) is unchanged by this study."
)

#: Variable-name key of each combination ("mu_s N/M" -> "mu_s_N_over_M").
COMBINATION_KEYS = {c: c.replace("/", "_over_").replace(" ", "_") for c in COMBINATIONS}

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


def analyse(r: FamilyFit) -> _Analysis:
    """Ranges of the parameters and combinations of one fitted problem, from the straight-line profiles and
    the profile likelihood together."""
    p, fit, ident, pid = r.problem, r.fit, r.identification, r.profile
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
        combo_rows = {n: rows[n] for n in c_lo if len(COMBINATIONS[n]) > 1}
        ranges = quantity_ranges(p, v, pid, {**dict(zip(p.free, np.eye(len(p.free)))), **combo_rows})
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
    # no quantity the equations leave free (exact, so the same on every CPU) is a point: its range covers at
    # least its extent over the fit's fibre (where no profile traced it, as in the joint problem, the
    # straight-line ridges see only the fibre's straight part)
    loose = _loose_rows(r)
    if loose:
        lo, hi = p.log_bounds
        rows = np.array(list(loose.values()))
        ext = 10.0 ** fibre_extent(r.structure, tuple(p.free), np.log10(v), rows, lo, hi, p.plateau_pair)
        for n, (e_lo, e_hi) in zip(loose, ext):
            if n in p.free:
                i = p.free.index(n)
                lower[i], upper[i] = min(lower[i], e_lo), max(upper[i], e_hi)
            if n in c_lo:  # a combination, or a one-parameter one (sigma, v_p)
                c_lo[n], c_hi[n] = min(c_lo[n], e_lo), max(c_hi[n], e_hi)
    # nor is a quantity spanning more than a decade
    ridge = np.array(
        [bool(f) or q in loose for q, f in zip(p.free, ridge | _wider_than_a_decade(lower, upper))]
    )
    c_ridge = {n: c_ridge[n] or bool(_wider_than_a_decade(c_lo[n], c_hi[n])) or n in loose for n in c_ridge}
    dims, note = structural_count(r)
    return _Analysis(v, lower, upper, ridge, combos, c_lo, c_hi, dims, opens, c_ridge, note)


def structural_count(r: FamilyFit) -> tuple[float, str]:
    """(identifiable dimensions, note): the structural dimension derived from the equations (exact, the same
    on every CPU), capped by the number of reported numbers (m numbers fix at most m directions)."""
    s, m = float(r.structural_dimensions), len(r.problem.observations)
    if not np.isfinite(s):
        return np.nan, ""
    if m < s:
        return float(m), f"at most {m} of the {int(s)} structural dimensions: {m} reported numbers"
    return s, ""


def _loose_rows(r: FamilyFit) -> dict:
    """Name -> log10 row of each free parameter and combination the equations leave free (sigma: both)."""
    runs, free = r.structure or (), tuple(r.problem.free)
    rows = quantity_rows(r.problem).items()
    return {n: row for n, row in rows if runs and not identifiable_in_structure(runs, free, tuple(row))}


#: A quantity whose interval spans more than this ratio is never called identifiable.
IDENTIFIABLE_MAX_RATIO = 10.0


def _wider_than_a_decade(lower, upper):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.asarray(upper, dtype=float) / np.asarray(lower, dtype=float) > IDENTIFIABLE_MAX_RATIO


def _unidentified(q) -> bool:
    """Profiled: its profile stays within the threshold to a bound; otherwise: its range reaches a bound."""
    return not q.identifiable if q.profiled else bool(q.open_lower or q.open_upper)


# -- one family's fit as a dataset; a figure's dataset is the families concatenated -------------------------


def _cf(long_name: str, units: str = "1", **extra) -> dict:
    return {"units": units, "long_name": long_name, **extra}


def _flags(meanings: str, values=(0, 1)) -> dict:
    return {"flag_values": np.array(values, dtype=np.int8), "flag_meanings": meanings}


OPEN_FLAGS = _flags("bounded open_below open_above open_both", (0, 1, 2, 3))
#: Combinations of several parameters: their ranges have open flags of their own (sigma, v_p are parameters).
COMPOUND = [c for c, params in COMBINATIONS.items() if len(params) > 1]

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

#: A one-parameter combination named as its parameter (sigma) has one set of variables for both roles.
BOTH_ROLES = {
    c: {"comment": f"both the parameter {c} and its one-parameter combination"}
    for c, key in COMBINATION_KEYS.items()
    if key in PARAMS
}
#: Per-direction variables of the straight-line profiles (getter on ``identify.Profile``).
DIRECTION_FIELDS = {
    "direction_singular_value": lambda pr: pr.singular_value,
    "direction_kind": lambda pr: 0 if pr.structural else (1 if pr.unconstrained else 2),
    "profile_t_lower": lambda pr: pr.t_lower,
    "profile_t_upper": lambda pr: pr.t_upper,
    "profile_reaches_lower_bound": lambda pr: pr.bound_lower,
    "profile_reaches_upper_bound": lambda pr: pr.bound_upper,
    "profile_rise": lambda pr: pr.rise,
    "direction_is_ridge": lambda pr: pr.ridge,
}
LOO_COMMENT = "method: {} (linear: r_i / (1 - h_ii) at the best fit; refit: the problem refitted without it)"

#: The CF attributes of every variable of a figure dataset, in the order they are written.
VARIABLES = {
    **{
        f"{kind}_{param}": _cf(f"{SYMBOLS[param]}: {text}", UNITS[param])
        for kind, text in PARAMETER_KINDS.items()
        for param in PARAMS
    },
    **{
        f"samples_{param}": _cf(
            f"{SYMBOLS[param]}: posterior samples (emcee, after burn-in)",
            UNITS[param],
            comment="each sample is the set closest to the stated one with its motion",
        )
        for param in PARAMS
    },
    "on_ridge": _cf(
        "parameter not identifiable (1): reported as the range flat_lower..flat_upper, never a point",
        **_flags("pinned on_ridge"),
    ),
    "posterior_sd_log10": _cf(
        "posterior spread of log10 parameter",
        comment="sampled if the chain is >= 50 autocorrelation times long, else the Laplace (Gauss-Newton) "
        "spread; in the identifiable directions only (a ridge's extent is flat_lower..flat_upper)",
    ),
    "laplace_sd_log10": _cf("Laplace spread of log10 parameter"),
    "range_open": _cf(
        "side(s) where the parameter's range reaches its bound within the threshold (unbounded by the data)",
        **OPEN_FLAGS,
    ),
    **{
        f"{kind}_{COMBINATION_KEYS[c]}": _cf(text.format(c=c), COMBINATION_UNITS[c], **BOTH_ROLES.get(c, {}))
        for c in COMBINATIONS
        for kind, text in COMBINATION_KINDS.items()
    },
    **{
        f"range_open_{COMBINATION_KEYS[c]}": _cf(
            f"{c}: side(s) where its range reaches the bounds within the threshold", **OPEN_FLAGS
        )
        for c in COMPOUND
    },
    "likelihood_profile_offset": _cf(
        "log10 change of the quantity from the best fit at each point of its profile likelihood"
    ),
    "likelihood_profile_chi_square": _cf(
        "chi-square re-minimised over the other parameters with the quantity fixed (inf: no set within the "
        "bounds; a point within the threshold stops at the first set found there)",
        threshold_delta_chi2=PL_THRESHOLD,
        confidence="0.95 pointwise, one parameter",
    ),
    "likelihood_profile_fixed": _cf(
        "quantity fixed at its best fit to count a flat dimension (1)", **_flags("profiled fixed")
    ),
    "direction_vector": _cf("unit direction in log10 of the free parameters"),
    "direction_singular_value": _cf(
        "singular value of the residual Jacobian (per log10 unit); 0: structural or unconstrained"
    ),
    "direction_kind": _cf(
        "how the direction was found",
        flag_values=np.array([0.0, 1.0, 2.0]),
        flag_meanings="structural unconstrained profiled",
        comment="structural: exactly the same motion; unconstrained: beyond the number of reported numbers; "
        "profiled: a singular direction of the Jacobian",
    ),
    "profile_t_lower": _cf("lower end [log10 units] of the interval within the threshold"),
    "profile_t_upper": _cf("upper end [log10 units] of the interval within the threshold"),
    "profile_reaches_lower_bound": _cf("within the threshold down to the parameter bounds (1) or not (0)"),
    "profile_reaches_upper_bound": _cf("within the threshold up to the parameter bounds (1) or not (0)"),
    "profile_rise": _cf("largest chi-square rise above the profile's minimum within the interval"),
    "direction_is_ridge": _cf("ridge (1): not identifiable"),
    "residual": _cf("(measured - reported) / reading precision at the best fit"),
    "residual_stated": _cf("(measured - reported) / reading precision with the stated parameters"),
    "loo_residual": _cf("leave-one-out residual (number left out of the fit)", comment=LOO_COMMENT),
    "conflict_member": _cf("claim belongs to the minimal conflicting subset (1)", comment=CONFLICT_METHOD),
    "conflict_size": _cf("numbers in the minimal conflicting subset (0: no subset)"),
    "conflict_worst_residual": _cf("smallest worst |residual| any fit to the subset alone reached (> 1)"),
    "conflict_search_max_size": _cf(
        "largest subset size searched (NaN: not searched, the fit is consistent)"
    ),
    "conflict_subsets_fitted": _cf("subsets fitted alone (the others had a witness or held a conflict)"),
    "conflict_count": _cf("minimal conflicting subsets found"),
    "worst_residual": _cf("largest |residual| at the best fit"),
    "chi_square": _cf("sum of squared residuals at the best fit"),
    "consistent": _cf("verdict", **_flags("inconsistent consistent")),
    "fit_source": _cf("where the best fit comes from", **_flags("least_squares conflict_search_witness")),
    "identifiable_dimensions": _cf(
        "identifiable parameter directions: the structural dimension, at most the number of reported numbers",
        comment=IDENTIFIABILITY_METHOD,
        threshold_delta_chi2=PROFILE_THRESHOLD,
    ),
    "structural_dimensions": _cf(
        "rank of the derived combinations' log-Jacobian over the phases the best fit visits (exact)",
        comment="stickslip.inverse.structure; the same on every CPU",
    ),
    "ridge_directions": _cf("flat directions (ridges) of the free parameters"),
    "motion_dimensions": _cf("directions that change the motion at all (rank of the combination map)"),
    "free_parameters": _cf("free parameters of the fit"),
    "infeasible_fraction": _cf("fraction of sampler proposals that were infeasible"),
    "forward_evaluations": _cf("forward-model evaluations"),
    "chain_converged": _cf("chain >= 50 autocorrelation times (1) or not (0)"),
    "chain_steps": _cf("emcee steps per walker"),
    "cpu_time": _cf("process CPU time of the fit", "s"),
    "acceptance_fraction": _cf("emcee acceptance fraction per walker"),
    "autocorr_time": _cf("integrated autocorrelation time [steps] per identifiable coordinate"),
    "sample_log_likelihood": _cf("log-likelihood of each sample"),
}
#: Flags are bytes; every other variable is a float (NaN: none).
FLAGS = {"on_ridge", "range_open", "likelihood_profile_fixed", "conflict_member", "consistent", "fit_source"}
FLAGS |= {f"range_open_{COMBINATION_KEYS[c]}" for c in COMPOUND}
#: Where a family has fewer entries than another: no flag set, no conflict member (every other variable NaN).
ABSENT = {name: np.int8(0) for name in FLAGS} | {"conflict_size": 0.0}
#: Dimensions whose length varies between families: labelled by position to be aligned.
RAGGED = ("sample", "walker", "coordinate", "profile_point", "direction", "conflict")


def open_flag(a: _Analysis, name: str) -> int:
    """0 bounded, 1 open below, 2 open above, 3 both (see QuantityRange)."""
    lo, hi = a.opens.get(name, (False, False))
    return int(lo) + 2 * int(hi)


@dataclass(frozen=True)
class FamilyFit:
    """One family's fitted problem (``study.fit_problem``): what its dataset and table rows are made of."""

    problem: Problem
    fit: BestFit
    region: Region | None
    loo: np.ndarray | None
    """Leave-one-out residuals, by ``loo_method``: "linear" (r_i / (1 - h_ii)) or "refit"."""
    loo_method: str
    stated_residuals: np.ndarray
    residual_noise: float
    conflicts: ConflictSearch | None
    identification: Identification | None
    profile: ProfileIdentification | None
    structural_dimensions: float
    phases: tuple
    structure: tuple
    fit_source: str
    forward: Forward
    cpu: float

    @cached_property
    def analysis(self) -> _Analysis:
        return analyse(self)

    @property
    def _likelihood_profiles(self) -> dict:
        return self.profile.profiles if self.profile else {}

    def to_dataset(self) -> xr.Dataset:
        """This family's variables with their CF attributes: each ragged dimension (``RAGGED``) as long as
        this family has entries, the parameters padded to all (a fixed one: no value, not on a ridge)."""
        p, a, fit, reg = self.problem, self.analysis, self.fit, self.region
        data = self._parameters() | self._profiles() | self._conflicts()
        data |= {
            "residual": ("claim", fit.residuals),
            "residual_stated": ("claim", self.stated_residuals),
            "loo_residual": (
                "claim",
                self.loo if self.loo is not None else np.full(len(fit.residuals), np.nan),
            ),
            "worst_residual": fit.worst,
            "chi_square": fit.chi2,
            "consistent": fit.consistent,
            "fit_source": self.fit_source == "conflict search",
            "identifiable_dimensions": a.dims,
            "structural_dimensions": self.structural_dimensions,
            "ridge_directions": len(p.free) - a.dims,
            "motion_dimensions": p.identifiable_basis().shape[1],
            "free_parameters": len(p.free),
            "infeasible_fraction": reg.infeasible_fraction if reg else np.nan,
            "forward_evaluations": self.forward.evaluations,
            "chain_converged": reg.converged if reg else np.nan,
            "chain_steps": reg.steps if reg else np.nan,
            "cpu_time": self.cpu,
            "acceptance_fraction": ("walker", reg.acceptance if reg else []),
            "autocorr_time": ("coordinate", reg.autocorr_time if reg else []),
            "sample_log_likelihood": ("sample", reg.log_likelihood if reg else []),
        }
        ds = xr.Dataset(
            {name: _variable(name, v) for name, v in data.items()},
            coords={
                "parameter": list(p.free),
                "quantity": np.array(list(self._likelihood_profiles), dtype=object),
            },
        )
        ds = ds.assign_coords({dim: np.arange(ds.sizes[dim]) for dim in RAGGED})
        ds = ds.reindex(parameter=list(PARAMS), fill_value=ABSENT | {"direction_vector": 0.0})
        combinations = self._combinations()  # sigma's variables written once, as the combination
        for kind in (*PARAMETER_KINDS, "samples"):  # one variable per parameter: each has its own units
            for j, param in enumerate(PARAMS):
                if f"{kind}_{param}" not in combinations:
                    ds[f"{kind}_{param}"] = ds[kind].isel(parameter=j, drop=True)
        ds = ds.drop_vars([*PARAMETER_KINDS, "samples"])
        ds = ds.assign({name: _variable(name, v) for name, v in combinations.items()})
        ds = ds.assign({name: ds[name].assign_attrs(VARIABLES[name]) for name in ds.data_vars})
        ds["loo_residual"].attrs["comment"] = LOO_COMMENT.format(self.loo_method)
        return ds

    def _parameters(self) -> dict:
        """Per free parameter (and the samples): the intermediate ``<kind>`` arrays of ``PARAMETER_KINDS``."""
        p, a, reg, jac = self.problem, self.analysis, self.region, self.fit.jacobian
        laplace = laplace_sd(p, jac) if np.all(np.isfinite(jac)) else np.full(len(p.free), np.nan)
        per_parameter = {
            "fit_point": a.fit_point,
            "best_fit": np.where(a.ridge, np.nan, a.fit_point),
            "flat_lower": a.lower,
            "flat_upper": a.upper,
            "stated": p.stated_free,
            "lower_bound": [p.bounds[k][0] for k in p.free],
            "upper_bound": [p.bounds[k][1] for k in p.free],
            "on_ridge": a.ridge,
            "posterior_sd_log10": reg.sd_log10 if reg else laplace,
            "laplace_sd_log10": reg.laplace_sd_log10 if reg else laplace,
            "range_open": [open_flag(a, q) for q in p.free],
        }
        samples = reg.samples_free if reg else np.zeros((0, len(p.free)))
        return {k: ("parameter", v) for k, v in per_parameter.items()} | {
            "samples": (("sample", "parameter"), samples)
        }

    def _combinations(self) -> dict:
        p, a = self.problem, self.analysis
        stated = p.combinations(p.stated_free)
        out = {}
        for c in COMBINATIONS:
            values = dict.fromkeys(COMBINATION_KINDS, np.nan)
            if c in a.combo_point:
                lo, hi = a.combo_lower.get(c, np.nan), a.combo_upper.get(c, np.nan)
                moves = bool(a.combo_ridge.get(c, False)) or not np.isfinite(lo)
                point = np.nan if moves else a.combo_point[c]
                values = {
                    "best_fit": point,
                    "flat_lower": lo,
                    "flat_upper": hi,
                    "stated": stated.get(c, np.nan),
                }
            out |= {f"{kind}_{COMBINATION_KEYS[c]}": v for kind, v in values.items()}
        return out | {f"range_open_{COMBINATION_KEYS[c]}": open_flag(a, c) for c in COMPOUND}

    def _profiles(self) -> dict:
        """The likelihood profiles (quantity x point) and the straight-line ones (direction)."""
        profiles, free = self._likelihood_profiles, self.problem.free
        points = max((len(pr.t) for pr in profiles.values()), default=0)
        t, chi2 = np.full((len(profiles), points), np.nan), np.full((len(profiles), points), np.nan)
        for j, pr in enumerate(profiles.values()):
            t[j, : len(pr.t)], chi2[j, : len(pr.t)] = pr.t, pr.chi2
        directions = self.identification.profiles if self.identification else []
        return {
            "likelihood_profile_offset": (("quantity", "profile_point"), t),
            "likelihood_profile_chi_square": (("quantity", "profile_point"), chi2),
            "likelihood_profile_fixed": ("quantity", np.zeros(len(profiles))),  # none: the structure counts
            "direction_vector": (
                ("direction", "parameter"),
                np.reshape([pr.direction for pr in directions], (len(directions), len(free))),
            ),
            **{name: ("direction", [get(pr) for pr in directions]) for name, get in DIRECTION_FIELDS.items()},
        }

    def _conflicts(self) -> dict:
        search = self.conflicts
        found = search.conflicts if search else ()
        member = np.zeros((len(found), len(self.problem.observations)))
        for i, c in enumerate(found):
            member[i, list(c.members)] = 1
        return {
            "conflict_member": (("conflict", "claim"), member),
            "conflict_size": ("conflict", [len(c.members) for c in found]),
            "conflict_worst_residual": ("conflict", [c.worst for c in found]),
            "conflict_search_max_size": search.max_size if search else np.nan,
            "conflict_subsets_fitted": search.subsets_fitted if search else np.nan,
            "conflict_count": len(found) if search else np.nan,
        }


def _variable(name: str, value) -> tuple:
    """(dims, values) of one variable: a flag as bytes, anything else as floats; a bare value is a scalar."""
    dims, values = value if isinstance(value, tuple) else ((), value)
    return dims, np.asarray(values, dtype=np.int8 if name in FLAGS else float)


def _coords(families: list, problem: Problem, quantities: list) -> dict:
    obs = problem.observations
    table = {
        "family": ("family", families, "model family"),
        "parameter": ("parameter", PARAMS, "parameter (BeltParams field)"),
        "parameter_units": ("parameter", [UNITS[p] for p in PARAMS], "units of the parameter"),
        "parameter_symbol": ("parameter", [SYMBOLS[p] for p in PARAMS], "symbol of the parameter"),
        "claim": ("claim", [o.claim for o in obs], "claim id (config/claims)"),
        "claim_unit": ("claim", [o.unit for o in obs], "unit of the reported number"),
        "claim_metric": ("claim", [o.metric for o in obs], "measured metric"),
        "claim_figure": ("claim", [o.figure for o in obs], "figure of the reported number"),
        "quantity": ("quantity", quantities, "quantity profiled (free parameter or combination)"),
    }
    return {
        key: (dim, np.array(v, dtype=object), {"long_name": text}) for key, (dim, v, text) in table.items()
    }


def figure_dataset(name: str, results: dict[str, FamilyFit], inverse: Inverse) -> xr.Dataset:
    """One figure (or the joint problem): the families' datasets along ``family``; each variable has units."""
    parts = [r.to_dataset() for r in results.values()]
    ds = xr.concat(
        parts,
        dim="family",
        join="outer",
        data_vars="all",
        coords="minimal",
        compat="override",
        fill_value=ABSENT,
    )
    # every family's quantities in the order first profiled ([""]: none); the ragged dimensions at least one
    # long, the walkers and the coordinates (a parameter each) whole
    quantities = list(dict.fromkeys(q for part in parts for q in part.quantity.values)) or [""]
    whole = {"walker": inverse.mode_settings.walkers, "coordinate": len(PARAMS), "direction": len(PARAMS)}
    lengths = {dim: max(ds.sizes[dim], 1) for dim in RAGGED} | whole
    ds = ds.reindex(
        {"quantity": quantities, **{d: np.arange(n) for d, n in lengths.items()}}, fill_value=ABSENT
    )
    first = next(iter(results.values())).problem
    out = xr.Dataset(
        {n: (ds[n].dims, ds[n].values, ds[n].attrs) for n in VARIABLES},
        coords=_coords(list(results), first, quantities),
    )
    out.attrs.update(
        title=f"FIT (inverse study): {first.title}",
        interpretation=INTERPRETATION,
        figure=name,
        settings=json.dumps(inverse.settings_record, sort_keys=True),
        runs=json.dumps([{"name": r.name, "overrides": r.overrides} for r in first.runs], default=str),
        identifiability_method=IDENTIFIABILITY_METHOD,
        conflict_method=CONFLICT_METHOD,
    )
    return out
