"""The common trajectory type and interface of every integration method."""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

#: Phase codes stored per sample: slip with v < V_b, stick, slip with v > V_b.
SLIP_BACKWARD, STICK, SLIP_FORWARD = -1, 0, 1


class SolverError(RuntimeError):
    """A method could not proceed (step-size collapse, non-finite state, no progress)."""


@dataclass
class SolverStats:
    """Work counters of one solve; ``status`` is 'ok' or 'failed' with ``message`` saying why."""

    rhs_evaluations: int = 0
    steps: int = 0
    rejected_steps: int = 0
    events: int = 0
    failures: int = 0
    cpu_time: float = 0.0
    status: str = "ok"
    message: str = ""
    jacobian_evaluations: int = 0
    min_step: float = float("nan")
    """Smallest accepted step [s] (methods that report one)."""


@dataclass
class Trajectory:
    """Samples of one solution on ``t`` plus the method's own switching record where it has one.

    ``segments`` (exact methods only) lists (t_start, t_end, phase) of every stick/slip segment, so
    interval lengths are known to machine precision rather than to the sample spacing.
    """

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    phase: np.ndarray
    belt_velocity: np.ndarray
    stats: SolverStats
    method: str
    settings: dict = field(default_factory=dict)
    segments: np.ndarray | None = None

    @property
    def ok(self) -> bool:
        return self.stats.status == "ok"

    @property
    def relative_velocity(self) -> np.ndarray:
        return self.v - self.belt_velocity


def classify_phase(v, vb, tolerance: float) -> np.ndarray:
    """Phase per sample of a smooth-method trajectory: stick where |v - V_b| <= tolerance."""
    vr = np.asarray(v) - np.asarray(vb)
    phase = np.sign(vr).astype(np.int8)
    phase[np.abs(vr) <= tolerance] = STICK
    return phase


class Timer:
    """Process CPU time of a block (insensitive to other load on the machine)."""

    def __enter__(self):
        self.start = time.process_time()
        return self

    def __exit__(self, *exc):
        self.elapsed = time.process_time() - self.start
        return False
