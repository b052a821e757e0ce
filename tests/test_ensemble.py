"""The perturbation ensemble: what it perturbs, what it stores, and that the claims table turns a margin
inside the numerical noise into 'indistinguishable' - never a status decided by the last digits."""

import numpy as np
import pytest
import xarray as xr
from hypothesis import given, settings
from hypothesis import strategies as st

from stickslip.claims.evaluate import evaluate
from stickslip.claims.rows import Claim
from stickslip.ensemble import (
    MEMBER_DIM,
    EnsembleSpec,
    declared,
    draw_sign,
    ensemble_dataset,
    members,
    perturbed_mapping,
    scaled_mapping,
)

MAPPING = {"params": {"mass": 1.0, "x0": 0.0, "n": 3, "flag": True}, "solver": {"safety_factor": 0.9}}
FIELDS = ("params.mass", "params.x0", "solver.safety_factor")
RUN = {"run_id": "results/x.nc", "fields": FIELDS}


def test_perturbation_moves_every_declared_field_by_the_relative_size_and_leaves_the_rest_alone():
    out = perturbed_mapping(MAPPING, 1e-12, seed=1, **RUN)
    assert abs(out["params"]["mass"] - 1.0) == pytest.approx(1e-12, rel=1e-3)
    assert abs(out["solver"]["safety_factor"] - 0.9) == pytest.approx(0.9e-12, rel=1e-3)
    assert out["params"]["x0"] == 0.0 and out["params"]["n"] == 3 and out["params"]["flag"] is True
    assert perturbed_mapping(MAPPING, 1e-12, seed=1, **RUN) == out  # reproducible
    assert MAPPING["params"]["mass"] == 1.0  # the input is not touched
    undeclared = perturbed_mapping(MAPPING, 1e-12, seed=1, run_id="results/x.nc", fields=("params.mass",))
    assert undeclared["solver"]["safety_factor"] == 0.9


# A small FE-like config: the physical fields declared, the output window and the count not.
SMALL = {
    "defaults": {
        "beam": {"length": 100.0, "thickness": 1.0, "n_elements": 20},
        "solver": {"t_end": 0.1, "output_dt": 2.5e-6, "safety_factor": 0.9},
    },
    "readings": {"a": {"sigma": 0.5}, "b": {"sigma": 0.3, "mass": 1.0}},
    "sweeps": {"s": {"values": [0.0, 10.0, 20.0]}},
}
SMALL_FIELDS = ("beam.length", "beam.thickness", "solver.safety_factor", "readings.*.*", "sweeps.*.values")


def _leaves(node, path=""):
    if isinstance(node, dict):
        out = {}
        for k, v in node.items():
            out.update(_leaves(v, f"{path}.{k}" if path else k))
        return out
    if isinstance(node, list):
        return {f"{path}[{i}]": v for i, v in enumerate(node)}
    return {path: node}


def _draw(cfg, seed):
    return _leaves(perturbed_mapping(cfg, 1e-12, seed, run_id="results/fe/s.nc", fields=SMALL_FIELDS))


def _reversed(node):
    return {k: _reversed(v) for k, v in reversed(node.items())} if isinstance(node, dict) else node


@pytest.mark.parametrize("seed", range(1, 41))
def test_each_draw_depends_on_the_field_path_only_not_on_order_other_keys_or_int_spelling(seed):
    base = _draw(SMALL, seed)
    # every key of every level in the opposite order: the same value at every path
    assert _draw(_reversed(SMALL), seed) == base
    # an unrelated reading (with floats) added first: every existing path keeps its value
    added = {**SMALL, "readings": {"new": {"sigma": 0.7, "plateau_speed": 0.6}, **SMALL["readings"]}}
    drawn = _draw(added, seed)
    assert {k: drawn[k] for k in base} == base
    # `mass: 1` for `mass: 1.0` draws the same float
    as_int = {**SMALL, "readings": {**SMALL["readings"], "b": {"sigma": 0.3, "mass": 1}}}
    assert _draw(as_int, seed) == base
    assert isinstance(base["readings.b.mass"], float) and base["readings.b.mass"] != 1.0
    # windows, samplings and counts are never perturbed
    for key in ("defaults.solver.t_end", "defaults.solver.output_dt", "defaults.beam.n_elements"):
        assert base[key] == _leaves(SMALL)[key]


def test_signs_are_balanced_and_differ_between_seeds_runs_and_fields():
    fields = [f"f{i}" for i in range(400)]
    signs = np.array([draw_sign(1, "results/a.nc", f) for f in fields])
    assert set(np.unique(signs)) == {-1.0, 1.0}
    # 400 fair draws: the fraction of + lies within 0.5 +- 0.1 (5 standard deviations)
    assert abs(np.mean(signs > 0) - 0.5) < 0.1
    other_seed = np.array([draw_sign(2, "results/a.nc", f) for f in fields])
    other_run = np.array([draw_sign(1, "results/b.nc", f) for f in fields])
    assert 0.3 < np.mean(signs == other_seed) < 0.7 and 0.3 < np.mean(signs == other_run) < 0.7


def test_declared_fields_match_a_path_or_its_tail_with_list_positions_dropped():
    assert declared("beam.length", ("beam.length",))
    assert declared("defaults.beam.length", ("beam.length",))
    assert declared("sweeps.angle.values[3]", ("sweeps.*.values",))
    assert not declared("defaults.solver.t_end", ("solver.safety_factor", "beam.length"))
    assert not declared("xbeam.length", ("beam.length",))


def test_step_member_only_where_a_step_setting_exists():
    assert scaled_mapping(MAPPING, 0.8, ("safety_factor",))["solver"]["safety_factor"] == pytest.approx(0.72)
    assert scaled_mapping({"params": {"mass": 1.0}}, 0.8, ("safety_factor",)) is None
    labels = [label for label, _, _ in members({"params": {"mass": 1.0}}, EnsembleSpec(), **RUN)]
    assert labels == ["base", "perturbed-1", "perturbed-2", "blas-threads-1"]
    assert "step" in [label for label, _, _ in members(MAPPING, EnsembleSpec().without_blas(), **RUN)]


def test_a_blas_member_that_would_repeat_the_base_run_is_not_run():
    """A job already limited to one BLAS thread (as Snakemake runs it) computes the blas-threads-1 member's
    exact numbers in its base run: that member is left out, any other limit kept."""
    mapping = {"params": {"mass": 1.0}}
    labels = [label for label, _, _ in members(mapping, EnsembleSpec(), **RUN, blas_threads_now=1)]
    assert labels == ["base", "perturbed-1", "perturbed-2"]
    labels = [label for label, _, _ in members(mapping, EnsembleSpec(), **RUN, blas_threads_now=2)]
    assert labels[-1] == "blas-threads-1"


@pytest.mark.parametrize(
    "bad,key",
    [
        ({"relative": -1}, "relative"),
        ({"step_factor": 1.5}, "step_factor"),
        ({"seedz": [1]}, "seedz"),
        ({"window_factor": 1.0}, "window_factor"),
        ({"window_factor": 3.0}, "window_factor"),
    ],
)
def test_bad_ensemble_settings_name_their_key(bad, key, repo_root):
    from stickslip.pipeline.config import ConfigError, load_config, validate_config

    config = load_config(sorted((repo_root / "config").glob("*.yaml")))
    config["ensemble"].update(bad)
    with pytest.raises(ConfigError, match=f"ensemble.{key}"):
        validate_config(config, producible=["results/onedof/friction_mu_vr.csv"])


def test_ensemble_dataset_stacks_every_metric_per_member_base_first():
    def build(cfg):
        m = cfg["params"]["mass"]
        return xr.Dataset(
            {"amplitude": ((), 2.0 * m), "series": ("time", np.arange(3.0) * m), "curve": ("k", [m, 2 * m])}
        )

    ds = ensemble_dataset(build, MAPPING, EnsembleSpec(blas_threads=None), **RUN)
    assert list(ds[f"{MEMBER_DIM}_label"].values) == ["base", "perturbed-1", "perturbed-2", "step"]
    assert list(ds[MEMBER_DIM].values) == [0, 1, 2, 3]
    assert ds.amplitude_ensemble.dims == (MEMBER_DIM,) and ds.curve_ensemble.dims == (MEMBER_DIM, "k")
    assert "series_ensemble" not in ds  # time series are the base run's only
    assert float(ds.amplitude_ensemble[0]) == float(ds.amplitude) == 2.0
    assert 0 < np.ptp(ds.amplitude_ensemble.values) < 1e-11


def test_a_member_that_fails_to_measure_makes_the_spread_infinite():
    def build(cfg):
        return xr.Dataset({"a": ((), 1.0 if cfg["params"]["mass"] == 1.0 else np.nan)})

    ds = ensemble_dataset(build, MAPPING, EnsembleSpec(blas_threads=None), **RUN)
    row = _value_row(reported=1.5, tol=0.1)
    res = _evaluate(row, "", lambda path: ds)
    assert res.spread == np.inf and res.status == "indistinguishable"


def _evaluate(row: dict, reading, open_dataset):
    """The claims table's evaluation of a row written here as a mapping, typed as the loader types it."""
    return evaluate(_typed(row), reading, open_dataset)


def _typed(row: dict) -> Claim:
    """``row`` as a claims file would hold it: figures and evidence class added, a value row's unit and
    tolerance reason filled in, and a compare or trend row without the value keys it may not hold."""
    row = {"figures": [2], "evidence": "evidence", **row}
    if row["kind"] in ("value", "ratio"):
        row = {"unit": "1", **row, "tolerance": {"reason": "test", **row["tolerance"]}}
    else:
        row = {k: v for k, v in row.items() if k not in ("value", "tolerance", "unit")}
        if row["kind"] == "compare":
            row = {k: v for k, v in row.items() if k not in ("dataset", "variable")}
    return Claim.model_validate(row)


def _value_row(reported, tol):
    return {
        "id": "x",
        "section": "3",
        "figure": "Fig. 2",
        "quote": "q",
        "kind": "value",
        "dataset": "d.nc",
        "variable": "a",
        "value": reported,
        "tolerance": {"rel": tol},
        "expected": "deviates",
    }


def _with_members(values):
    return xr.Dataset(
        {"a": ((), values[0]), "a_ensemble": ((MEMBER_DIM,), np.asarray(values, float))},
        coords={MEMBER_DIM: [f"m{i}" for i in range(len(values))]},
    )


def test_margin_and_spread_of_a_value_claim():
    # reported 1.0 +- 10 %: the accepted band ends at 1.1; measured 1.2 is 0.1 outside, spread 0.01
    res = _evaluate(_value_row(1.0, 0.1), "", lambda p: _with_members([1.2, 1.205, 1.195]))
    assert res.status == "deviates"
    assert res.margin == pytest.approx(0.1) and res.spread == pytest.approx(0.01)
    near = _evaluate(_value_row(1.0, 0.1), "", lambda p: _with_members([1.11, 1.12, 1.10]))
    assert near.status == "indistinguishable" and "below the numerical noise" in near.reason


def test_compare_claim_on_two_equal_numbers_is_indistinguishable_not_deviating():
    """The case that broke the build on a fresh machine: 9.454e-6 > 9.454e-6 decided by rounding."""
    lhs, rhs = (
        _with_members([9.4540e-6, 9.5150e-6, 9.4100e-6]),
        _with_members([9.4540e-6, 9.5130e-6, 9.4300e-6]),
    )
    row = {
        **_value_row(0, 0),
        "kind": "compare",
        "lhs": {"dataset": "l.nc", "variable": "a"},
        "relation": ">",
        "rhs": {"dataset": "r.nc", "variable": "a"},
    }
    res = _evaluate(row, "", lambda p: {"l.nc": lhs, "r.nc": rhs}[p])
    assert res.status == "indistinguishable" and res.margin == 0.0 and res.spread > 0


@settings(max_examples=200, deadline=None)
@given(
    measured=st.floats(0.0, 3.0),
    noise=st.floats(0.0, 0.2),
    shifts=st.lists(st.floats(-1.0, 1.0), min_size=2, max_size=4),
    move=st.floats(0.0, 1.0),
)
def test_a_decided_status_survives_any_move_of_the_measurement_within_its_spread(
    measured, noise, shifts, move
):
    """Property behind the 3-spread rule: if a claim is decided (reproduced/deviates), putting the measured
    value anywhere inside the ensemble's range decides it the same way."""
    values = [measured] + [measured + noise * s for s in shifts]
    row = _value_row(1.0, 0.1)
    res = _evaluate(row, "", lambda p: _with_members(values))
    if res.status not in ("reproduced", "deviates"):
        return
    lo, hi = min(values), max(values)
    moved = [lo + move * (hi - lo)] + values[1:]
    assert _evaluate(row, "", lambda p: _with_members(moved)).status in (res.status, "indistinguishable")
    moved_res = _evaluate({**row, "tolerance": {"rel": 0.1}}, "", lambda p: xr.Dataset({"a": ((), moved[0])}))
    assert moved_res.status == res.status  # the plain decision on the moved value is unchanged


def test_trend_claim_spread_from_the_members_curves():
    x = np.array([1.0, 2.0, 3.0])
    base = np.array([1.0, 1.02, 1.04])  # +4 % of the mean: just under the 5 % no-trend floor
    members_ = np.stack([base, base * [1, 1, 1.02], base * [1, 1, 0.98]])
    ds = xr.Dataset(
        {"f": ("p", base), "f_ensemble": ((MEMBER_DIM, "p"), members_)},
        coords={"p": x, MEMBER_DIM: ["base", "a", "b"]},
    )
    row = {**_value_row(0, 0), "kind": "trend", "dataset": "s.nc", "variable": "f", "coord": "p", "sign": 0}
    res = _evaluate(row, "", lambda p: ds)
    assert res.status == "indistinguishable" and res.spread > 0


def test_identical_members_decide_even_at_zero_margin():
    """0 > 0 in every member (no separation at all) is robustly false: deviates, not indistinguishable."""
    zero = _with_members([0.0, 0.0, 0.0])
    row = {
        **_value_row(0, 0),
        "kind": "compare",
        "lhs": {"dataset": "l.nc", "variable": "a"},
        "relation": ">",
        "rhs": {"value": 0.0},
    }
    res = _evaluate(row, "", lambda p: zero)
    assert res.status == "deviates" and res.margin == 0.0 and res.spread == 0.0


def test_window_member_starts_the_steady_window_later_and_only_where_a_run_has_one():
    spec = EnsembleSpec(seeds=(), window_factor=1.25, blas_threads=None)
    run = {"defaults": {"transient": 10.0, "t_end": 40.0}}
    labels = {label: m for label, m, _ in members(run, spec, **RUN)}
    assert labels["window"]["defaults"] == {"transient": 12.5, "t_end": 40.0}
    assert "window" not in {label for label, *_ in members({"fe": {"t_end": 1.0}}, spec, **RUN)}
    assert "window" not in {label for label, *_ in members({"transient": 0.0}, spec, **RUN)}
    with pytest.raises(ValueError, match="window_factor"):
        EnsembleSpec(window_factor=1.0)


def test_window_member_leaves_a_limit_cycle_alone_and_unsettles_a_decaying_run():
    """Fig. 2 in the consistent reading is a stick-slip limit cycle: its amplitude does not depend on where
    the steady window starts. In Eq. 4 as printed the run decays to rest, and what is left at the window's
    start is all its 'amplitude' measures: the window member moves it by far more than the base value's 3
    spreads could ever tolerate, so such a number decides nothing."""
    from stickslip import simulate

    def spread(reading):
        ds = simulate("fig02", reading=reading, ensemble=True)
        members = ds["amplitude_peak_to_peak_ensemble"].values
        labels = list(ds[f"{MEMBER_DIM}_label"].values)
        assert "window" in labels
        return float(np.ptp(members)) / abs(float(members[0]))

    assert spread("consistent_caption") < 1e-2
    assert spread("eq4_caption") > 0.5
