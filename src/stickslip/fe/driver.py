"""The one driver of the compiled engine: step schedule, chunking, progress, state sampling, the result.

Both explicit models (the beam or its reduced model on a point contact,
:func:`stickslip.fe.explicit.integrate`; the plane-stress strip on slave nodes,
:func:`stickslip.fe.continuum.integrate_continuum`) build their engine pieces (structure, contact, recorder)
and their initial state, then hand them to :func:`drive`, which advances
:func:`stickslip.fe.engine.run_steps` chunk by chunk, and to :func:`pack_result`, which turns the
recorder's arrays into an :class:`ExplicitResult`. The arithmetic of every step lives in the engine; this
module only decides where the chunks end, so a result does not depend on which model called it.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from .engine import run_steps

SEPARATED, STICK, SLIP = 0, 1, 2
STATE_NAMES = ("separation", "stick", "slip")


@dataclass
class ExplicitResult:
    t: np.ndarray
    x: np.ndarray  #: horizontal displacement of the contact point [mm]
    y: np.ndarray  #: vertical displacement [mm]
    vx: np.ndarray  #: horizontal velocity [mm s-1]
    vy: np.ndarray  #: vertical velocity [mm s-1]
    normal_force: np.ndarray  #: [N]
    friction_force: np.ndarray  #: friction on the beam along the disc velocity [N]
    slip_velocity: np.ndarray  #: beam minus disc tangential velocity [mm s-1]
    state: np.ndarray  #: 0 separated, 1 stick, 2 slip (per sample)
    dt: float
    dt_crit: float
    n_steps: int
    step_counts: dict  #: steps in each contact state over the whole run
    cpu_time: float
    static_normal_force: float
    q_static: np.ndarray
    q_samples: np.ndarray | None = None
    v_samples: np.ndarray | None = None
    extra: dict = field(default_factory=dict)

    def fractions(self, window: str = "all") -> dict:
        """Fractions of increments per contact state, over the whole run or (``second_half``) over the
        increments after half the duration (the window the amplitude metrics use)."""
        c = self.step_counts if window == "all" else self.extra.get("second_half_counts", self.step_counts)
        tot = max(sum(c.values()), 1)
        return {k: v / tot for k, v in c.items()}


def named_counts(c) -> dict:
    """Steps per contact state, by name."""
    return {name: int(c[k]) for k, name in enumerate(STATE_NAMES)}


def critical_step(omega: float, beta: float) -> float:
    """Central-difference limit [s] at angular frequency ``omega`` with stiffness-proportional damping beta
    [s] on the lagged velocity: (2/w)(sqrt(1 + xi^2) - xi), xi = beta w / 2."""
    xi = 0.5 * beta * omega
    return 2.0 / omega * (math.sqrt(1.0 + xi * xi) - xi)


def schedule(duration: float, dt_crit: float, dt, safety_factor: float, output_interval):
    """(dt, steps, sampling stride, samples) of a run of ``duration``: ``dt`` None is safety_factor x
    dt_crit; a sample every ``output_interval`` (None: every step), sample 0 (the start) included."""
    if dt is None:
        dt = safety_factor * dt_crit
    n_steps = int(math.ceil(duration / dt - 1e-9))
    every = max(1, int(round((output_interval or dt) / dt)))
    return dt, n_steps, every, n_steps // every + 1


@dataclass
class Run:
    """What :func:`drive` did: the next sample index ``j`` (= samples written), the last step the engine
    did (``n_done``: the sampled step of a blow-up), the end of the last chunk (``chunk_end``), the counts
    per state over the run and (``halves``) over its first half, and the sampled states."""

    j: int
    n_done: int
    chunk_end: int
    diverged: bool
    counts: np.ndarray
    first_half: np.ndarray | None
    cpu_time: float
    q_samples: list = field(default_factory=list)
    v_samples: list = field(default_factory=list)


def drive(
    structure, contact, recorder, u: np.ndarray, v: np.ndarray, *, n_steps: int, every: int, dt: float,
    blowup: float, chunk: int, progress=None, halves: bool = False, sample_state: bool = False,
) -> Run:  # fmt: skip
    """Advance steps 1 .. ``n_steps`` of the engine in place on ``u``, ``v``, the recorder's sample 0 written.

    Chunks are ``chunk`` steps long; ``halves`` ends a chunk at step ``n_steps // 2`` to count the states of
    the second half apart; ``sample_state`` makes the chunks ``every`` steps long and keeps a copy of u, v
    at the end of each chunk that ends on a sampled step. ``progress(done, total)`` is called after every
    chunk. Stops after the chunk in which a displacement exceeds ``blowup`` (checked at sampled steps).
    """
    counts = np.zeros(3, dtype=np.int64)
    length = every if sample_state else chunk
    n_half = n_steps // 2 if halves else -1
    first_half = counts.copy() if halves else None
    run = Run(1, 0, 0, False, counts, first_half, 0.0)
    t0 = time.process_time()
    n0 = 1
    while n0 <= n_steps:
        n1 = min(n_steps, n0 + length - 1)
        if n0 <= n_half < n1:  # a chunk ends at the half-way step, to count the second half's states
            n1 = n_half
        run.j, run.n_done, run.diverged = run_steps(
            n0, n1, every, run.j, dt, blowup, u, v, counts, structure, contact, recorder
        )
        run.chunk_end = n1
        if n1 == n_half:
            run.first_half = counts.copy()
        if sample_state and n1 % every == 0:
            run.q_samples.append(u.copy())
            run.v_samples.append(v.copy())
        if progress is not None:
            progress(run.n_done, n_steps)
        if run.diverged:
            break
        n0 = n1 + 1
    run.cpu_time = time.process_time() - t0
    return run


def pack_result(
    rows: np.ndarray, state: np.ndarray, run: Run, *, n_steps: int, dt: float, dt_crit: float,
    static_normal_force: float, q_static: np.ndarray, q_samples=None, v_samples=None,
) -> ExplicitResult:  # fmt: skip
    """The result of ``run``: ``rows`` are the recorder's 8 series by row (t, x, y, vx, vy, normal force,
    friction force, slip velocity; a recorder that writes them by column passes its array transposed), cut
    at the ``run.j`` samples written; ``n_steps`` is the step count the caller reports."""
    m = run.j
    series = (rows[k, :m].copy() for k in range(8))
    res = ExplicitResult(
        *series, state=state[:m].copy(), dt=dt, dt_crit=dt_crit, n_steps=n_steps,
        step_counts=named_counts(run.counts), cpu_time=run.cpu_time, static_normal_force=static_normal_force,
        q_static=q_static, q_samples=q_samples, v_samples=v_samples,
    )  # fmt: skip
    res.extra["diverged"] = bool(run.diverged)
    if run.first_half is not None:
        res.extra["second_half_counts"] = named_counts(run.counts - run.first_half)
    return res
