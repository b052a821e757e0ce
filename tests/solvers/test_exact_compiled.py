"""The compiled exact solver (the pipeline's method ``exact``) against its pure-Python reference.

Both run the same algorithm on the same closed forms; they differ only in the elementary functions (libm's
exp/sin/cos in the kernel, numpy's in the reference: an ulp apart). Tolerance, and why:

* the same events: the same number of segments, the same phase sequence, the same counters and statuses
  (the hypothesis test compares the segments longer than ``T_TOL``: see ``assert_agree``);
* segment ends within ``T_TOL`` = 1e-9 s (all runs here are 15-40 s long with periods of 0.01-3 s). Brent's
  method stops within xtol + rtol |tau| = 1e-15 + 8.9e-16 tau (< 4e-14 s at 40 s); an ulp of difference in
  the gap moves a transversal root by ulp / |gap'| (a graze is found as the simple root of gap'), and that
  state error is carried into the next segment and can grow with the slip's e^{alpha tau}. Measured: at most
  1.4e-14 s over the 300 seeded runs of ``benchmarks/check_exact_bits.py`` and every config scene; 1e-9 s
  leaves that amplification five orders of magnitude, while a different event (a missed graze, another
  release) moves an end by a visible fraction of a period (>= 1e-4 s even on the si scene's 2e-4 s grid);
* samples x, v within ``REL`` = 1e-9 of the run's own scale (largest finite |x|, |v|): measured <= 4e-13
  (the largest on the overflowing si scene, where the free motion's terms cancel), and NaN exactly where
  the reference has NaN (a run that overflows). Over random parameters the scale is that of the terms the
  closed form sums (``term_scales``): a stiff overdamped slip cancels terms 1e6 times larger than v, so
  both implementations evaluate v only to ~1e-10 of it;
* per-sample phase identical except at a sample within ``T_TOL`` of a segment end.

A slip that starts on the plateau surface |v_r| = v_p leaves it where the outer law's acceleration points; a
state within ``PLATEAU_BAND`` (1e-9 of v_p) counts as on it. The band was 1e-12: an event on the surface
leaves the state off it by the closed form's rounding, and 56 of 30000 random 10 s runs (both solvers) landed
1-2e-12 on the side they were leaving and failed on 'zero-length segments in a row'. The band is wide against
that rounding and narrow against any physical speed, so the outcome no longer depends on the last bits
(``test_a_slip_that_ends_on_the_plateau_surface_goes_on``).

Known limits, from random sweeps beyond the 60 fixed examples (``benchmarks/sweep_exact_agreement.py``, the
range of ``params_strategy``, these tolerances):

* ``uniform --seed 2..4 --runs 1000`` (si reading, belt decelerating at 0.2 mm/s^2, where a random sweep had
  once reported a ZeroDivisionError in the kernel): 0 disagreements in 3000 runs; the error did not recur.
* ``ends --seed 11..14 --runs 1000`` (each parameter at an end of its range 30 % of the time): 5
  disagreements in 4000 runs, all in the si reading with a plateau, at the plateau surface |v_r| = v_p. Four
  combine it with a printed sign (eq3_printed, eq4_printed), which no pipeline reading does (the API does not
  refuse it): the state chatters across the surface in segments of ~1e-6 s, a different sequence in each
  solver (the solver never slides along a surface), and in one the reference stops on 'zero-length segments
  in a row' where the kernel runs on. One is consistent (v_p = 2): a 1.6e-7 s plateau excursion taken by one
  solver only.

"""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from stickslip.analysis.divergence import BoundedSolver
from stickslip.inverse.forward import StaticKineticSolver, build_model
from stickslip.model import PAPER_BASELINE, BeltModel
from stickslip.model.laws import LawModel, law_from_config
from stickslip.model.params import BeltParams, ParameterError
from stickslip.solvers import CompiledExactSolver, ExactSwitchSolver, make_solver
from stickslip.solvers.exact_compiled import python_reference
from stickslip.studies.specs import run_spec

T_TOL = 1e-9
REL = 1e-9


def _scale(a):
    finite = np.abs(a[np.isfinite(a)])
    return max(float(finite.max(initial=0.0)), 1e-300)


def _digits_masked(text):
    import re

    return re.sub(r"[-+]?\d[\d.e+-]*", "#", text)


def term_scales(segments):
    """How far either implementation's rounding reaches, per run: (x scale, v scale, condition).

    * a slip's v = p1 + alpha x_h + ... sums terms of size |alpha h0| + |q| + |p1| (x: |p0| + |h0| + |p1|
      duration) that cancel to a much smaller v in a stiff overdamped slip (e.g. |alpha| = 2e4 /s in the si
      reading): the rounding is eps times these, not times |v| (the scales);
    * a growing segment carries its start state's rounding, eps (|x0| + |p0|) in h0 and eps (|v0| + |p1| +
      |alpha| (|x0| + |p0|)) in q, at the rate of its growing mode: relative to the motion it is that
      rounding over the growing mode's own amplitude (the condition). A run that starts next to an unstable
      sliding equilibrium (h0 = 3e-8 x0) and grows away from it keeps its start's last bits 3e7-fold."""
    sx = sv = 0.0
    condition = 1.0
    for seg in segments:
        mo = seg.motion
        if not hasattr(mo, "_alpha"):
            continue
        (p0, p1), (h0, _) = mo._p, mo._h
        sx = max(sx, abs(p0) + abs(h0) + abs(p1) * (seg.t1 - seg.t0))
        sv = max(sv, abs(mo._alpha * h0) + abs(mo._q) + abs(p1))
        a0 = abs(mo.x0) + abs(p0)
        a1 = abs(mo.v0) + abs(p1) + abs(mo._alpha) * a0
        if mo._w2 < 0.0 and mo._alpha + mo._w > 0.0:  # x_h's e^{(alpha + w) tau} term grows
            growing = abs(h0 + mo._q / mo._w) / 2.0
            carried = (a0 + a1 / mo._w) / 2.0
        elif mo._w2 > 0.0 and mo._alpha > 0.0:  # e^{alpha tau} (h0 cos + q sin / w) grows
            growing = float(np.hypot(h0, mo._q / mo._w))
            carried = a0 + a1 / mo._w
        else:
            continue
        condition = max(condition, carried / growing if growing > 0.0 else np.inf)
    return sx, sv, condition


def assert_agree(ref, got, strict=True, terms=(0.0, 0.0, 1.0)):
    """Trajectories of the reference and the compiled solver: same events, same samples within tolerance.

    ``strict=False`` (random parameters): segments shorter than ``T_TOL`` are left out of the comparison. A
    state that lands within rounding of a switching surface (the plateau |v_r| = v_p, a graze) may take one
    more rounding-level segment (~1e-15 s) in one solver than in the other, as the last bits decide; the
    physical events (every longer segment, its phase and its ends) and the samples must still agree, and
    each solver counts one step per segment."""
    assert got.method == ref.method and got.settings == ref.settings
    if strict:
        assert (got.stats.status, got.stats.message) == (ref.stats.status, ref.stats.message)
    else:  # a failure message names the state to 17 digits: the last may differ
        assert got.stats.status == ref.stats.status
        assert _digits_masked(got.stats.message) == _digits_masked(ref.stats.message)
    ref_seg, got_seg = ref.segments, got.segments
    if strict:
        assert (got.stats.steps, got.stats.events, got.stats.failures) == (
            ref.stats.steps,
            ref.stats.events,
            ref.stats.failures,
        )
    else:
        assert got.stats.failures == ref.stats.failures
        if ref.ok:
            assert (ref.stats.steps, got.stats.steps) == (len(ref_seg), len(got_seg))
        ref_seg, got_seg = (s[s[:, 1] - s[:, 0] > T_TOL] for s in (ref_seg, got_seg))
    assert got_seg.shape == ref_seg.shape
    np.testing.assert_array_equal(got_seg[:, 2], ref_seg[:, 2])
    np.testing.assert_allclose(got_seg[:, :2], ref_seg[:, :2], rtol=0, atol=T_TOL)
    np.testing.assert_array_equal(got.t, ref.t)
    np.testing.assert_array_equal(got.belt_velocity, ref.belt_velocity)
    for name, term in zip(("x", "v"), terms[:2]):
        a, b = getattr(ref, name), getattr(got, name)
        np.testing.assert_array_equal(np.isnan(b), np.isnan(a), err_msg=name)
        # rtol: a growing segment's start rounding, relative to the motion it grows into (term_scales)
        rtol = REL * terms[2] if terms[2] > 1.0 else 0.0
        np.testing.assert_allclose(b, a, rtol=rtol, atol=REL * max(_scale(a), term), err_msg=name)
    differ = np.nonzero(got.phase != ref.phase)[0]
    if differ.size:  # only a sample that sits on a segment end (to the time tolerance) may be labelled apart
        ends = ref.segments[:, 1]
        near = np.min(np.abs(ref.t[differ, None] - ends[None, :]), axis=1) <= T_TOL
        assert near.all(), f"phase differs at t = {ref.t[differ[~near]]}"


def solve_both(solver, model, t_end, t_eval=None):
    with np.errstate(all="ignore"):  # diverging runs are data here
        return python_reference(solver).solve(model, t_end, t_eval), solver.solve(model, t_end, t_eval)


def test_the_pipeline_method_exact_is_the_compiled_solver():
    solver = make_solver("exact")
    assert isinstance(solver, CompiledExactSolver) and solver.name == "exact"
    assert solver.settings == ExactSwitchSolver().settings
    assert isinstance(build_model(PAPER_BASELINE, "consistent")[1], CompiledExactSolver)
    assert isinstance(build_model(PAPER_BASELINE, "consistent", mu_k_ratio=0.8)[1], StaticKineticSolver)
    assert isinstance(StaticKineticSolver(static_force=5.0), CompiledExactSolver)


def _config_runs():
    import yaml

    from stickslip.schema import Onedof

    from project_run import ROOT

    onedof = Onedof.model_validate(yaml.safe_load((ROOT / "config" / "config.yaml").read_text())["onedof"])
    return onedof, [(scene, reading) for scene in onedof.scenes for reading in onedof.readings]


CONFIG, CONFIG_RUNS = _config_runs()


@pytest.mark.parametrize("scene, reading", CONFIG_RUNS, ids=[f"{s}-{r}" for s, r in CONFIG_RUNS])
def test_every_config_scene_and_reading_agrees_with_the_reference(scene, reading):
    """Every scene x reading of config/config.yaml as the pipeline runs it (its t_end and samples), also
    through BoundedSolver (the diverging/overflowing runs come back with the same status and message)."""
    spec = run_spec(CONFIG, scene, reading, "exact")
    solver = spec.solver()
    assert isinstance(solver, CompiledExactSolver)
    assert_agree(*solve_both(solver, spec.model, spec.t_end, spec.t_eval))
    bounded = [BoundedSolver(s, spec.transient) for s in (python_reference(solver), solver)]
    ref, got = (b.solve(spec.model, spec.t_end, spec.t_eval) for b in bounded)
    assert (got.stats.status, got.stats.message) == (ref.stats.status, ref.stats.message)


def test_the_config_covers_every_kind_of_outcome():
    """The runs above include a stick-slip cycle, a diverging run, one that overflows (non-finite), a
    reading that never sticks and a belt that stops with the mass held at rest."""
    outcomes = {}
    for scene, reading in CONFIG_RUNS:
        spec = run_spec(CONFIG, scene, reading, "exact")
        with np.errstate(all="ignore"):
            tr = BoundedSolver(spec.solver(), spec.transient).solve(spec.model, spec.t_end, spec.t_eval)
        stuck = tr.segments[(tr.segments[:, 2] == 0) & (tr.segments[:, 1] > tr.segments[:, 0])]
        outcomes[(scene, reading)] = (tr.stats.status, tr.stats.message, len(stuck))
    assert outcomes[("fig02", "consistent_caption")][::2] == ("ok", 12)  # the paper's stick-slip cycle
    assert outcomes[("fig07", "consistent_caption")][0] == "diverged"
    assert "non-finite" in outcomes[("fig02", "consistent_si")][1]
    assert outcomes[("fig02", "eq3_caption")][::2] == ("ok", 0)  # never sticks
    assert outcomes[("fig15", "consistent_caption")][0] == "ok"  # the belt stops at 20 s, the mass rests


def test_segments_are_the_references_segment_objects(baseline05):
    solver = CompiledExactSolver()
    ref = python_reference(solver).segments(baseline05, 20.0)
    got = solver.segments(baseline05, 20.0)
    assert [s.phase for s in got] == [s.phase for s in ref]
    for a, b in zip(ref, got):
        assert type(a.motion) is type(b.motion)
        assert (b.t0, b.t1) == pytest.approx((a.t0, a.t1), rel=0, abs=T_TOL)
        t = np.linspace(b.t0, b.t1, 7)
        np.testing.assert_allclose(np.array(b.state(t)), np.array(a.state(t)), rtol=0, atol=1e-12)


@pytest.mark.parametrize(
    "changes",
    [
        dict(sigma=0.3),  # zero slip damping: grazes every period
        dict(sigma=0.5, x0=0.85),  # starts at the release point
        dict(sigma=0.5, belt_deceleration=0.2),  # belt stops inside the first slip
        dict(sigma=0.5, belt_velocity=5.0),  # above the critical speed: no stick
        dict(sigma=0.5, units="si", damping=0.5),  # one slip over thousands of periods (growing windows)
        dict(sigma=0.5, plateau_speed=0.6, belt_deceleration=0.025),
    ],
)
def test_hard_scenes_agree(changes):
    solver = CompiledExactSolver()
    for variant in ("consistent", "eq3_printed", "eq4_printed"):
        model = BeltModel.build(PAPER_BASELINE.with_(**changes), variant)
        assert_agree(*solve_both(solver, model, 20.0))


def test_coarse_sampling_still_catches_every_graze(baseline03):
    assert_agree(*solve_both(CompiledExactSolver(samples_per_period=4), baseline03, 20.0))


@pytest.mark.parametrize("mu_k_ratio, eq4_term", [(1.0, True), (0.8, False), (0.7, True)])
def test_the_inverse_studys_own_laws_agree(mu_k_ratio, eq4_term):
    """The static/kinetic solver (stick limit above the slip friction) and Eq. 4's term as printed."""
    for params in (PAPER_BASELINE.with_(sigma=0.5), PAPER_BASELINE.with_(sigma=0.3, plateau_speed=0.6)):
        model, solver = build_model(params, "consistent", eq4_term=eq4_term, mu_k_ratio=mu_k_ratio)
        assert_agree(*solve_both(solver, model, 30.0))


def test_an_affine_law_model_is_converted_and_other_laws_refused_as_by_the_reference():
    params = PAPER_BASELINE.with_(sigma=0.5)
    affine = LawModel(params, law_from_config({"kind": "affine", "mu_s": 0.5, "sigma": 0.5}))
    assert_agree(*solve_both(CompiledExactSolver(), affine, 20.0))
    stribeck = LawModel(params, law_from_config({"kind": "stribeck", "mu_s": 0.5, "mu_k": 0.3, "v_s": 0.5}))
    errors = []
    for solver in (ExactSwitchSolver(), CompiledExactSolver()):
        with pytest.raises(ParameterError) as info:
            solver.solve(stribeck, 5.0)
        errors.append(str(info.value))
    assert errors[0] == errors[1]


def test_a_run_over_its_segment_budget_fails_as_the_reference_does(baseline05):
    ref, got = solve_both(CompiledExactSolver(max_segments=3), baseline05, 40.0, np.linspace(0, 40, 81))
    assert got.stats.status == "failed" and "more than 3 segments" in got.stats.message
    assert_agree(ref, got)


def test_root_search_port_matches_scipy_and_reports_its_errors():
    """The kernel's Brent iteration against scipy.optimize.brentq on one slip's gap, and the two errors
    scipy raises (NaN value, no sign change) as status codes."""
    from scipy.optimize import brentq as scipy_brentq

    from stickslip.solvers import exact_kernel as kernel
    from stickslip.solvers.linear import LinearSegment

    seg = LinearSegment(m=1.0, c=-1.0, k=5.0, g0=-5.0, g1=0.0, x0=0.85, v0=0.5)
    S = kernel._slip_setup(1.0, -1.0, 5.0, -5.0, 0.0, 0.85, 0.5, -1.0, 0.5, 0.0, np.inf, 0.0, 0.0)

    def gap(tau):
        return -(float(seg.state(tau)[1]) - 0.5)

    for lo, hi in ((0.5, 2.5), (1.0, 2.3)):
        want = scipy_brentq(gap, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)
        root, status, _ = kernel.brentq(0, S, lo, hi)
        assert status == kernel.OK and root == pytest.approx(want, rel=0, abs=1e-14)
    assert kernel.brentq(0, S, 0.5, 0.6)[1] == kernel.ROOT_SIGN
    nan_s = kernel._slip_setup(1.0, -1.0, 5.0, -5.0, 0.0, np.nan, 0.5, -1.0, 0.5, 0.0, np.inf, 0.0, 0.0)
    assert kernel.brentq(0, nan_s, 0.5, 2.5)[1] == kernel.ROOT_NAN


params_strategy = st.fixed_dictionaries(
    {
        "mass": st.floats(0.1, 10.0),
        "stiffness": st.floats(0.5, 50.0),
        "damping": st.floats(0.0, 5.0),
        "sigma": st.floats(0.0, 1.0),
        "mu_s": st.floats(0.05, 1.5),
        "normal_force": st.floats(1.0, 100.0),
        "belt_velocity": st.floats(0.05, 2.0),
        "x0": st.floats(-1.0, 1.0),
        "v0": st.floats(-1.0, 1.5),
        "belt_deceleration": st.sampled_from([0.0, 0.0, 0.025, 0.2]),
        "plateau_speed": st.sampled_from([np.inf, np.inf, 0.6, 2.0]),
        "units": st.sampled_from(["as_given", "as_given", "as_given", "si"]),
    }
)


# derandomized: the same 60 examples on every machine and run. Random draws had found, about once in six
# runs, a diverging run whose samples differ by its start's rounding times its growth (term_scales'
# condition, now in the tolerance); wider random sweeps still find rare disagreements at the belt's stop in
# the si reading (module docstring), which a CI run must not meet by chance.
@settings(max_examples=60, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(params_strategy, st.sampled_from(["consistent", "consistent", "eq3_printed", "eq4_printed"]))
def test_property_agrees_with_the_reference_over_physical_parameters(changes, variant):
    model = BeltModel.build(BeltParams(**changes), variant)
    try:
        ref, got = solve_both(CompiledExactSolver(), model, 10.0, np.linspace(0.0, 10.0, 501))
    except ValueError as exc:  # the reference's root search refused (overflow): the kernel must too
        with pytest.raises(type(exc), match="NaN|signs"), np.errstate(all="ignore"):
            CompiledExactSolver().solve(model, 10.0, np.linspace(0.0, 10.0, 501))
        return
    assert got.stats.status == ref.stats.status, (got.stats.message, ref.stats.message)
    terms = (0.0, 0.0, 1.0)
    if ref.ok:  # (a failed run has NaN samples: nothing to scale)
        with np.errstate(all="ignore"):
            terms = term_scales(python_reference(CompiledExactSolver()).segments(model, 10.0))
    assert_agree(ref, got, strict=False, terms=terms)


#: random parameters whose runs ended a slip 1-2e-12 of v_p off the plateau surface, on the side they were
#: leaving, and failed with the old 1e-12 band (module docstring)
PLATEAU_SURFACE_RUNS = [
    (dict(mass=0.7420393504480197, stiffness=47.46818331943917, damping=0.3692879000664945,
          sigma=0.10029026400041796, mu_s=0.9543956839707648, normal_force=87.1582369492536,
          belt_velocity=0.9218951093520944, x0=-0.6115271379625726, v0=-0.6070230895921651,
          belt_deceleration=0.025, plateau_speed=0.6), "eq4_printed"),
    (dict(mass=0.31978262691129555, stiffness=25.17598288235089, damping=0.8975887242653002,
          sigma=0.41481189279570463, mu_s=1.3271754085443337, normal_force=68.41510034758764,
          belt_velocity=0.5952166881218818, x0=-0.4594462689868577, v0=-0.7449150193841122,
          belt_deceleration=0.025, plateau_speed=0.6), "eq4_printed"),
    (dict(mass=0.5330889917186118, stiffness=27.91494322563895, damping=0.11298176754935885,
          sigma=0.25170987422955937, mu_s=1.0921965033629364, normal_force=67.15674541661686,
          belt_velocity=0.5070886123721777, x0=0.8870194293768852, v0=-0.3640227857039121,
          belt_deceleration=0.2, plateau_speed=0.6), "eq3_printed"),
]  # fmt: skip


@pytest.mark.parametrize("changes,variant", PLATEAU_SURFACE_RUNS)
def test_a_slip_that_ends_on_the_plateau_surface_goes_on(changes, variant):
    from stickslip.solvers import exact, exact_kernel

    assert exact_kernel.PLATEAU_BAND == exact.PLATEAU_BAND  # one rule in both implementations
    model = BeltModel.build(BeltParams(**changes), variant)
    ref, got = solve_both(CompiledExactSolver(), model, 10.0, np.linspace(0.0, 10.0, 501))
    assert ref.stats.status == got.stats.status == "ok", (ref.stats.message, got.stats.message)
    assert_agree(ref, got, strict=False)
