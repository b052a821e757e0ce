"""Modes of a built beam-on-disc scene with the contact held, the fields along the beam, the mid-span
node's motion, and the growth of the first contact-held mode (measured on a trajectory, and the linear
estimate from the sliding system's eigenvalues)."""

from __future__ import annotations

import numpy as np

from . import mechanics as mc
from .beam import modal_analysis
from .metrics import leading_growth_rate, mode_amplitude
from .stability import null_space, sliding_eigenvalues


def contact_held_modes(scene, n_modes: int = 40) -> tuple[np.ndarray, np.ndarray]:
    """Natural frequencies [Hz] and mode shapes (free-DOF columns) of the beam with the contact held
    (bilateral normal constraint)."""
    s = scene.system
    if scene.law.method == "fixed_normal" or not np.any(s.c_n):
        return modal_analysis(s.K, s.M, n_modes)
    Z = null_space(s.c_n)
    freq, phi = modal_analysis(Z.T @ s.K @ Z, Z.T @ s.M @ Z, n_modes)
    return freq, Z @ phi


def natural_frequencies(scene) -> np.ndarray:
    """Natural frequencies [Hz] of the beam with the contact held (bilateral normal constraint)."""
    return contact_held_modes(scene)[0]


def nodal_field(scene, q: np.ndarray, component: int) -> np.ndarray:
    """Per-node values of one DOF component (0 axial, 1 vertical, 2 rotation) of a free-DOF vector q;
    zero at constrained DOFs (the clamp, the held transverse motion of Section 10)."""
    full = np.zeros(3 * scene.beam.n_nodes)
    full[scene.beam.free] = q
    return full[component::3].copy()


#: recorded mid-span components: (name, DOF component), in the order of the recorded columns
MIDSPAN_COMPONENTS = (("horizontal", 0), ("vertical", 1))


def midspan_dofs(scene) -> np.ndarray:
    """Indices (among the free DOFs) of the mid-span node's axial and vertical DOFs, in the order of
    MIDSPAN_COMPONENTS; -1 for a held DOF (its series is then zero)."""
    free = scene.beam.free
    node = scene.params.beam.n_elements // 2
    out = []
    for _, comp in MIDSPAN_COMPONENTS:
        dof = 3 * node + comp
        k = int(np.searchsorted(free, dof))
        out.append(k if k < free.size and free[k] == dof else -1)
    return np.array(out, dtype=np.int64)


def midspan_motion(scene, r, dofs: np.ndarray) -> dict:
    """Displacement (from the start) and velocity of the mid-span node, a node off the contact, per
    component: {'horizontal': (x, v), 'vertical': (y, v)}; zeros where that DOF is held."""
    out = {}
    col = 0
    for (name, _), k in zip(MIDSPAN_COMPONENTS, dofs, strict=True):
        if k < 0 or r.q_samples is None:
            out[name] = (np.zeros_like(r.t), np.zeros_like(r.t))
            continue
        q = r.q_samples[:, col]
        out[name] = (q - q[0], r.v_samples[:, col].copy())
        col += 1
    return out


#: demodulation window of the first-mode amplitude [s] (18 periods of the 366 Hz bending mode)
MODE_WINDOW = 0.05


def linear_growth_rate(scene, frequency: float, solver) -> float:
    """Re(lambda) [s-1] of the linearised sliding system's eigenvalue nearest ``frequency`` [Hz]: the
    mode's negative-damping growth rate from mu'(V) at the disc speed, with the scene's Rayleigh damping
    (stickslip.fe.stability; the closed form -N mu' a^2/2 - beta w^2/2 of the propped bending mode agrees
    with it to 1 %). Section 10 (normal force held, transverse motion held): the closed form for the first
    axial mode, whose tangential amplitude at the tip is sqrt(2/(rho A L)) at unit modal mass."""
    if scene.law.method == "fixed_normal":
        b = scene.params.beam
        return (
            mc.negative_damping_growth_rate(
                scene.law.fixed_normal_force,
                scene.law.friction.slope(scene.law.disc_speed),
                mc.axial_mode_tip_amplitude(b.rho * b.area, b.length),
                2 * np.pi * frequency,
                solver.stiffness_damping,
            )
            - 0.5 * solver.mass_damping
        )
    lam = sliding_eigenvalues(
        scene.system,
        scene.law,
        mass_damping=solver.mass_damping,
        stiffness_damping=solver.stiffness_damping,
    )
    return float(lam[np.argmin(np.abs(np.abs(lam.imag) / (2 * np.pi) - frequency))].real)


def mode_growth(r, frequency: float) -> tuple[dict, tuple]:
    """Growth of node 1's horizontal amplitude at ``frequency`` [Hz] (any model's trajectory): metrics (the
    growth rate fitted to the leading segment, stickslip.fe.metrics, its end, the frequency) and the
    amplitude series (window centres [s], amplitudes [mm]) per MODE_WINDOW."""
    tc, amp = mode_amplitude(r.t, r.x - r.x[0], frequency, MODE_WINDOW)
    rate, end = leading_growth_rate(tc, amp)
    return {
        "first_mode_growth_rate": rate,
        "first_mode_growth_end": end,
        "first_mode_frequency": float(frequency),
    }, (tc, amp)


def first_mode_growth(scene, r, frequency: float, solver) -> tuple[dict, tuple]:
    """The first contact-held mode's growth at node 1 (mode_growth) and the linear estimate of its rate
    (linear_growth_rate)."""
    m, series = mode_growth(r, frequency)
    return {**m, "first_mode_growth_rate_linear": linear_growth_rate(scene, frequency, solver)}, series
