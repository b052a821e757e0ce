"""The minimal beam model made right: rotary inertia, lower-face contact, damping, drop start, readings,
convergence in element count and step, and the corrected stability analysis."""

import numpy as np
import pytest

from stickslip.fe.beam import element_mass
from stickslip.fe.explicit import static_state
from stickslip.fe.params import BeamParams, FrictionTable, SceneParams, SolverParams
from stickslip.fe.scene import build_scene
from stickslip.fe.stability import max_growth, sliding_eigenvalues, sliding_state, transient_growth
from stickslip.studies.fe_config import scene_mapping
from stickslip.studies.fe_scene import run_scene

FIG17 = FrictionTable.paper_fig17()
RHO_I = 7850e-12 * 1.0 / 12.0  # rho * I of the 1 x 1 mm steel section [t mm]


@pytest.mark.parametrize("le", [0.5, 2.0, 5.0])
def test_consistent_rotary_inertia_of_a_rigid_rotation_is_exact(le):
    # v = x*theta, theta = 1 on one element: rotary kinetic energy 2*T = rho*I*le exactly
    with_ri = element_mass(7850e-12, np.array([le]), "consistent", RHO_I)[0]
    without = element_mass(7850e-12, np.array([le]), "consistent", 0.0)[0]
    q = np.array([0.0, 0.0, 1.0, 0.0, le, 1.0])
    assert q @ (with_ri - without) @ q == pytest.approx(RHO_I * le, rel=1e-12)


def test_lumped_rotary_inertia_adds_half_element_to_each_node():
    le = np.array([1.0, 3.0])
    d = element_mass(7850e-12, le, "lumped", RHO_I) - element_mass(7850e-12, le, "lumped", 0.0)
    np.testing.assert_allclose(d[:, 2, 2], RHO_I * le / 2)
    np.testing.assert_allclose(d[:, 5, 5], RHO_I * le / 2)
    assert np.count_nonzero(d) == 4


def _face_mass_ratio(n, rotary):
    """Effective tangential mass of the lower-face contact point over that of the axis node."""
    out = []
    for off in (True, False):
        m = {"beam": {"n_elements": n, "rotary_inertia": rotary}, "contact": {"surface_offset": off}}
        s = build_scene(SceneParams.from_mapping(m), FIG17).system
        minv = 1.0 / np.diag(s.M)  # lumped: diagonal
        out.append(1.0 / (s.c_t**2 @ minv))
    return out[0] / out[1]


def test_lower_face_tangential_mass_tends_to_a_quarter_only_with_rotary_inertia():
    # W_tt = 1/m_u + (h/2)^2/m_theta; with m_theta -> rho*I*le/2 = m_u h^2/12 the face point keeps
    # 1/(1 + 3) of the node's tangential mass as le -> 0. With HRZ alone m_theta ~ le^3 and it vanishes.
    with_ri = [_face_mass_ratio(n, True) for n in (100, 400)]
    without = [_face_mass_ratio(n, False) for n in (100, 400)]
    assert with_ri[1] == pytest.approx(0.25, rel=0.03)
    assert abs(with_ri[1] - with_ri[0]) < abs(with_ri[0] - 0.25)  # approaching the limit
    assert without[1] < 0.01 and without[1] < 0.1 * without[0]


def test_drop_start_rings_at_the_propped_cantilever_frequency():
    # clamped-pinned first mode: (beta L)^2 = 3.9266^2; the lower-face prop is h/2 off the axis (<1 %)
    p = BeamParams()
    f_cp = 3.92660231**2 / (2 * np.pi * p.length**2) * np.sqrt(p.E * p.inertia / (p.rho * p.area))
    mp = {
        "beam": {"n_elements": 20},
        "disc": {"surface_speed_mm_s": 19.9},
        "solver": {
            "t_end": 0.03,
            "initial_state": "drop",
            "stiffness_damping": 5e-9,
            "output_dt": 5e-6,
        },
    }
    _, m, _ = run_scene(mp, FIG17)
    assert m["dominant_frequency"] == pytest.approx(f_cp, rel=0.01)
    assert m["horizontal_amplitude"] > 1e-5  # the drop bends the beam: tens of nanometres at node 1


def test_static_start_on_the_axis_has_no_bending_at_angle_zero():
    mp = {
        "disc": {"surface_speed_mm_s": 19.9},
        "contact": {"surface_offset": False},
        "solver": {"t_end": 0.01, "initial_state": "static"},
    }
    r, _, _ = run_scene(mp, FIG17)
    assert np.abs(r.y - r.y[0]).max() < 1e-15


@pytest.mark.parametrize("n_el", [10, 20, 40])
def test_response_converges_in_element_count_and_step(n_el):
    # amplitude, centre and frequency of node 1 within 5 % of a 40-element run at half the step
    def metrics(n, sf):
        mp = {
            "beam": {"n_elements": n},
            "disc": {"surface_speed_mm_s": 0.5},
            "solver": {"t_end": 0.03, "initial_state": "drop", "stiffness_damping": 5e-9,
                       "output_dt": 2.5e-6, "safety_factor": sf},
        }  # fmt: skip
        return run_scene(mp, FIG17)[1]

    ref = metrics(40, 0.45)
    got = metrics(n_el, 0.9)
    for q in ("horizontal_amplitude", "mean_horizontal_displacement", "dominant_frequency"):
        assert got[q] == pytest.approx(ref[q], rel=0.05), q


def test_readings_layer_between_defaults_and_scene():
    import yaml

    from stickslip.schema.fe import Fe

    from project_run import ROOT

    layers = {
        "defaults": {"solver": {"initial_state": "drop"}, "contact": {"surface_offset": True}},
        "readings": {
            "a": {},
            "b": {"contact": {"surface_offset": False}, "solver": {"initial_state": "static"}},
        },
    }
    fe = yaml.safe_load((ROOT / "config" / "fe.yaml").read_text())["fe"]
    scenes = {**fe["scenes"], "s": {"solver": {"initial_state": "drop"}}}
    cfg = Fe.model_validate({**fe, **layers, "scenes": scenes})
    assert scene_mapping(cfg, "s")["contact"]["surface_offset"] is True  # first reading is the default
    mb = scene_mapping(cfg, "s", "b")
    assert mb["contact"]["surface_offset"] is False and mb["solver"]["initial_state"] == "drop"
    with pytest.raises(ValueError, match="readings.c"):
        scene_mapping(cfg, "s", "c")


def test_bad_solver_and_contact_values_name_their_key():
    with pytest.raises(ValueError, match="stiffness_damping"):
        SolverParams(stiffness_damping=-1.0)
    with pytest.raises(ValueError, match="output_node"):
        SceneParams.from_mapping({"contact": {"output_node": "node7"}})
    with pytest.raises(ValueError, match="direction"):
        SceneParams.from_mapping({"disc": {"speed_rev_per_min": 1.0, "direction": "left"}})


@pytest.mark.parametrize("angle,sign", [(30.0, -1), (-30.0, 1)])
def test_sliding_normal_force_includes_the_friction_preload(angle, sign):
    m = {"beam": {"n_elements": 20}, "disc": {"surface_speed_mm_s": 0.5}, "contact": {"angle_deg": angle}}
    s = build_scene(SceneParams.from_mapping(m), FIG17)
    n_static = static_state(s.system, s.law)[1]
    q, n_slide = sliding_state(s.system, s.law)
    assert np.sign(n_slide - n_static) == sign and abs(n_slide / n_static - 1) > 0.1
    # equilibrium: K q = f + N (c_n + mu c_t) with the gap closed
    mu = FIG17(0.5)
    res = s.system.K @ q - s.system.f - n_slide * (s.system.c_n + mu * s.system.c_t)
    assert np.abs(res).max() < 1e-9 * np.abs(s.system.f).max()
    assert abs(s.system.c_n @ q) < 1e-12


@pytest.mark.parametrize("angle,slope", [(-30.0, -1 / 6), (0.0, -1 / 6), (30.0, -0.05)])
def test_eigenvalue_growth_matches_the_transient_within_10_percent(angle, slope):
    m = {"beam": {"n_elements": 20}, "disc": {"surface_speed_mm_s": 0.5}, "contact": {"angle_deg": angle}}
    lin = FrictionTable.linear(FIG17(0.5) - slope * 0.5, slope, 1.0)
    s = build_scene(SceneParams.from_mapping(m), lin)
    g, f = max_growth(sliding_eigenvalues(s.system, s.law, stiffness_damping=5e-9))
    gt, ft = transient_growth(s.system, s.law, min(0.05, 8 / g), stiffness_damping=5e-9)
    assert gt == pytest.approx(g, rel=0.10)
    assert ft == pytest.approx(f, rel=0.01)  # the mode that grows is the least stable eigenvalue's
    assert f == pytest.approx(12.9e3, rel=0.01)  # the first axial mode, not a mesh mode
