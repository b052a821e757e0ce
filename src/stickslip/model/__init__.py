"""Layer 1: parameters, friction laws, equations of motion, amplitude curves."""

from .equations import BeltModel
from .friction import VARIANTS, AffineFriction, friction_law
from .params import PAPER_BASELINE, UNIT_READINGS, BeltParams, ParameterError

__all__ = [
    "BeltModel",
    "VARIANTS",
    "AffineFriction",
    "friction_law",
    "PAPER_BASELINE",
    "UNIT_READINGS",
    "BeltParams",
    "ParameterError",
]
