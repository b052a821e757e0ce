"""Layer 1: parameters, friction laws, equations of motion, amplitude curves."""

from .equations import BeltModel
from .friction import VARIANTS, AffineFriction, friction_law
from .laws import LAW_KINDS, FrictionLaw, LawModel, law_from_config
from .params import PAPER_BASELINE, UNIT_READINGS, BeltParams, ParameterError

__all__ = [
    "BeltModel",
    "VARIANTS",
    "AffineFriction",
    "friction_law",
    "LAW_KINDS",
    "FrictionLaw",
    "LawModel",
    "law_from_config",
    "PAPER_BASELINE",
    "UNIT_READINGS",
    "BeltParams",
    "ParameterError",
]
