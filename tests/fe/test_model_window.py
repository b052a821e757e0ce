"""The model comparison over a claim's window: the separation-burst metric, the agreement rule of the
window rows (both models at dt and dt/2) and the note every disagreeing row carries."""

import math

import numpy as np
import pytest
import xarray as xr

from stickslip.fe.metrics import BURST_WINDOW, separation_burst_time
from stickslip.studies.fe_comparison import window_agrees, window_dataset, window_rows


def _state(t, bursts):
    """Contact state (1 stick, 0 separated): separated every k-th sample inside each (t0, t1, k)."""
    state = np.ones(t.size, dtype=np.int8)
    for t0, t1, k in bursts:
        idx = np.flatnonzero((t >= t0) & (t < t1))
        state[idx[::k]] = 0
    return state


def test_burst_time_is_the_first_window_at_half_the_largest_separated_share():
    t = np.arange(0.0, 1.0, 2.5e-6)
    # chatter separates 2 % of the samples from 0.1 s, the burst 50 % from 0.42 s, later chatter 10 %
    state = _state(t, [(0.1, 0.42, 50), (0.42, 0.45, 2), (0.6, 1.0, 10)])
    assert separation_burst_time(t, state) == pytest.approx(0.42, abs=BURST_WINDOW)
    # scale-free: the same pattern at a tenth of the separated shares gives the same time
    quiet = _state(t, [(0.1, 0.42, 500), (0.42, 0.45, 20), (0.6, 1.0, 100)])
    assert separation_burst_time(t, quiet) == pytest.approx(0.42, abs=BURST_WINDOW)


def test_burst_time_is_nan_without_separation():
    t = np.arange(0.0, 0.1, 1e-5)
    assert math.isnan(separation_burst_time(t, np.ones(t.size, dtype=np.int8)))


@pytest.mark.parametrize(
    "beam,continuum,quantity,expected",
    [
        ((0.565, 0.560), (0.523, 0.570), "separation_burst_time", True),  # ranges overlap
        ((0.565, 0.560), (0.540, 0.545), "separation_burst_time", True),  # no overlap, means within 5 %
        ((0.565, 0.560), (0.40, 0.41), "separation_burst_time", False),  # apart by 38 %
        ((0.565, 0.560), (-0.1, 0.570), "separation_burst_time", False),  # a sign differs
        ((0.565, float("nan")), (0.523, 0.570), "separation_burst_time", False),  # a value missing
        ((float("nan"),) * 2, (float("nan"),) * 2, "separation_burst_time", True),  # no burst in both
        # the beam moves 2x under step halving: its wide range overlaps the continuum's but backs nothing
        ((32.1, 68.7), (31.0, 32.4), "max_normal_force_ratio", False),
        # a growth rate's claims read its sign: a sign converged under step halving may agree
        ((0.565, 0.536), (0.523, 0.570), "first_mode_growth_rate", True),
    ],
)
def test_window_agreement_rule(beam, continuum, quantity, expected):
    assert window_agrees(beam, continuum, quantity=quantity) is expected


def _scene(growth, burst, t_end=1.0, converged=True):
    """A scene dataset as the step-halving check leaves it (rate, half step, full step if not converged)."""
    data = {
        "first_mode_growth_rate": growth[0] if converged else math.nan,
        "first_mode_growth_rate_half_step": growth[1],
        "separation_burst_time": burst[0],
        "separation_burst_time_half_step": burst[1],
    }
    if not converged:
        data["first_mode_growth_rate_full_step"] = growth[0]
    return xr.Dataset(data, attrs={"t_end": t_end})


def test_window_rows_read_the_full_step_value_and_note_every_disagreement():
    cont = {"s": _scene((0.52, 0.57), (0.42, 0.43))}
    beam = {"s": _scene((0.56, 0.30), (0.60, 0.61), converged=False)}
    rows = {r["quantity"]: r for r in window_rows(cont, beam, {"s.separation_burst_time": "explained"})}
    growth, burst = rows["first_mode_growth_rate"], rows["separation_burst_time"]
    # the not-converged beam rate is compared at its full step, not as the NaN the claims read
    assert growth["beam"] == 0.56 and growth["beam_half_step"] == 0.30
    assert growth["agreement"] is True  # [0.30, 0.56] overlaps [0.52, 0.57]
    assert burst["agreement"] is False and burst["note"] == "explained"
    assert growth["t_end"] == 1.0 and growth["window"] == "claim"
    no_note = window_rows(cont, beam, {})
    assert all(r["note"] for r in no_note if not r["agreement"])
    ds = window_dataset(list(rows.values()))
    assert ds["window_beam_value"].sel(window_scene="s", window_quantity="first_mode_growth_rate").values == (
        pytest.approx([0.56, 0.30])
    )
    assert int(ds["window_agreement"].sel(window_scene="s", window_quantity="separation_burst_time")) == 0


def test_every_scalar_both_models_hold_at_both_steps_is_compared_and_equal_values_agree():
    from stickslip.studies.fe_comparison import window_quantities

    both = {"a": 1.0, "a_half_step": 1.0}
    both |= {"separation_burst_time": 0.4, "separation_burst_time_half_step": 0.4}
    beam = xr.Dataset({**both, "only_beam": 2.0, "only_beam_half_step": 2.0, "no_half": 3.0,
                       "series": ("t", [1.0, 2.0]), "series_half_step": ("t", [1.0, 2.0])})  # fmt: skip
    assert window_quantities(xr.Dataset(both), beam) == ["separation_burst_time", "a"]
    assert window_agrees((0.0, 0.0), (0.0, 0.0))  # no separation in either model at either step
    assert not window_agrees((0.0, 0.0), (0.1, 0.1))


def test_a_window_row_whose_beam_value_moves_under_step_halving_says_so():
    cont = {"s": _scene((0.52, 0.57), (0.42, 0.43))}
    beam = {"s": _scene((0.56, 0.55), (0.30, 0.60))}  # the burst moves 0.30 -> 0.60 s when dt is halved
    rows = {r["quantity"]: r for r in window_rows(cont, beam, {})}
    burst = rows["separation_burst_time"]
    assert burst["agreement"] is False  # although [0.30, 0.60] overlaps the continuum's [0.42, 0.43]
    assert burst["note"].startswith("the beam's value moves under step halving (0.3 at dt, 0.6 at dt/2)")
    # a note of the config's own takes precedence over the generic one
    noted = {r["quantity"]: r for r in window_rows(cont, beam, {"s.separation_burst_time": "explained"})}
    assert noted["separation_burst_time"]["note"] == "explained"
