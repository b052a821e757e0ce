"""A beam-on-disc scene's dataset does not depend on the BLAS thread count: the explicit engine calls no
BLAS, and the static, modal and sliding-eigenvalue solves on the 60-DOF beam stay below the size at which
the BLAS splits work between threads. So the FE scene jobs leave the perturbation ensemble's BLAS member
out (it would repeat the base run); on a machine where this fails they must put it back."""

import numpy as np
import pytest
from threadpoolctl import threadpool_limits

from stickslip.fe.params import FrictionTable
from stickslip.studies.fe_scene import scene_dataset
from stickslip.studies.fe_setup_fit import setup_fit_dataset

FIG17 = FrictionTable.paper_fig17()
BASE = {
    "beam": {"n_elements": 20},
    "solver": {"t_end": 0.01, "initial_state": "drop", "stiffness_damping": 5e-9},
}


@pytest.mark.parametrize(
    "over",
    [
        {"disc": {"surface_speed_mm_s": 0.5}, "contact": {"method": "kinematic"}},
        {"disc": {"speed_rev_per_min": 15.2}, "contact": {"method": "penalty", "penalty_stiffness": 1000.0}},
        {"disc": {"surface_speed_mm_s": 0.5}, "contact": {"method": "fixed_normal"}},
        {"disc": {"speed_rev_per_min": 15.2}, "contact": {"method": "kinematic", "angle_deg": 30.0}},
    ],
    ids=["kinematic", "penalty", "fixed_normal", "angle30"],
)
def test_scene_dataset_is_bit_identical_under_one_blas_thread(over):
    mapping = {**BASE, **over}
    many = scene_dataset(mapping, FIG17)
    with threadpool_limits(limits=1, user_api="blas"):
        one = scene_dataset(mapping, FIG17)
    differ = [
        name
        for name in many.data_vars
        if name != "cpu_time" and not np.array_equal(many[name].values, one[name].values, equal_nan=True)
    ]
    assert not differ, differ


def test_setup_fit_is_bit_identical_under_one_blas_thread():
    mapping = {
        **BASE,
        "disc": {"surface_speed_mm_s": 0.5},
        "contact": {"method": "penalty", "penalty_stiffness": 0.058},
    }
    many = setup_fit_dataset(mapping, FIG17, 0.058)
    with threadpool_limits(limits=1, user_api="blas"):
        one = setup_fit_dataset(mapping, FIG17, 0.058)
    assert all(
        np.array_equal(many[n].values, one[n].values, equal_nan=True)
        for n in many.data_vars
        if n != "cpu_time"
    )
