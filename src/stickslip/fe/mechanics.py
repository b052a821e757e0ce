"""Closed-form estimates of what the stated beam-on-disc setup can produce.

Small pure functions in the internal units (mm, s, N, t, MPa), each the hand calculation behind one kind
of paper claim: how far friction can stretch the beam, how far the tip rotation moves a face corner, the
beam's natural frequencies, how fast the falling friction law can grow a mode, how much slip a stated
stick duration implies, the disc's surface speed, and the normal load at a tilted contact. The tests hold
each against the finite-element model where both apply.
"""

from __future__ import annotations

import math

import numpy as np

#: (beta L) of the first clamped-free bending modes
CANTILEVER_BETA_L = (1.875104069, 4.694091133, 7.854757438)
#: (beta L) of the first clamped-pinned (propped) bending modes
PROPPED_BETA_L = (3.926602312, 7.068582745, 10.21017612)


def disc_surface_speed(rev_per_min: float, diameter: float) -> float:
    """Surface speed [mm s-1] of a disc of ``diameter`` [mm] turning at ``rev_per_min``: pi d n / 60."""
    return math.pi * diameter * rev_per_min / 60.0


def distributed_weight(rho: float, area: float, g: float) -> float:
    """Self-weight per length q = rho A g [N mm-1]."""
    return rho * area * g


def propped_reaction(q: float, length: float) -> float:
    """Prop (tip support) reaction of a clamped beam under uniform load q: 3 q L / 8 [N]."""
    return 3.0 * q * length / 8.0


def axial_friction_deflection(mu: float, normal_force: float, length: float, E: float, area: float) -> float:
    """Axial stretch [mm] of a clamped bar pulled at its tip by the friction force mu N: mu N L / (E A)."""
    return mu * normal_force * length / (E * area)


def tip_rotation(q: float, length: float, EI: float, support: str = "propped", k_tip: float = 0.0) -> float:
    """Magnitude of the tip rotation [rad] of a clamped beam under uniform load q with its tip

    * ``free``: q L^3 / (6 EI);
    * ``propped`` (rigid support): q L^3 / (48 EI), rotating the other way;
    * ``soft``: a spring ``k_tip`` [N mm-1] carries R = delta_free / (1/k + L^3/(3 EI)) of the load, the
      rotation is q L^3/(6 EI) - R L^2/(2 EI) (signed: positive as the free tip, negative as the propped).
    """
    free = q * length**3 / (6.0 * EI)
    if support == "free":
        return free
    if support == "propped":
        return q * length**3 / (48.0 * EI)
    if support == "soft":
        if not k_tip > 0:
            raise ValueError(f"k_tip: a soft support needs a positive stiffness, got {k_tip!r}")
        delta_free = q * length**4 / (8.0 * EI)
        R = delta_free / (1.0 / k_tip + length**3 / (3.0 * EI))
        return free - R * length**2 / (2.0 * EI)
    raise ValueError(f"support: must be 'free', 'propped' or 'soft', got {support!r}")


def zero_rotation_support_stiffness(EI: float, length: float) -> float:
    """Tip support stiffness [N mm-1] at which the loaded tip does not rotate: 24 EI / L^3. Softer supports
    turn the tip as a free one, stiffer ones as a propped one; a face corner's offset changes sign here."""
    return 24.0 * EI / length**3


def propped_deflection(q: float, length: float, EI: float, x: float) -> float:
    """Static deflection [mm] of a propped cantilever under uniform load at ``x`` from the clamp:
    q x^2 (3 L^2 - 5 L x + 2 x^2) / (48 EI); a drop start rings each point about it with this amplitude."""
    return q * x**2 * (3.0 * length**2 - 5.0 * length * x + 2.0 * x**2) / (48.0 * EI)


def propped_max_sag(q: float, length: float, EI: float) -> float:
    """Largest static deflection [mm] of a propped cantilever under uniform load: q L^4 / (184.6 EI), at
    x = 0.5785 L from the clamp (the mid-span region, away from the contact)."""
    return propped_deflection(q, length, EI, (15.0 - math.sqrt(33.0)) / 16.0 * length)


def corner_displacement(rotation: float, thickness: float) -> float:
    """Horizontal displacement [mm] of a face corner of the end section rotated by ``rotation``: theta h/2."""
    return rotation * thickness / 2.0


def soft_support_for_corner_displacement(
    target: float, q: float, length: float, EI: float, thickness: float
) -> float:
    """Tip support stiffness [N mm-1] whose static tip rotation moves a face corner by ``target`` [mm]
    (between the propped and the free values; bisection in log k)."""
    lo, hi = 1e-8, 1e8

    def f(k):
        return corner_displacement(tip_rotation(q, length, EI, "soft", k), thickness) - target

    if not f(lo) > 0 > f(hi):
        raise ValueError("target: outside the range a tip spring can give")
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return math.sqrt(lo * hi)


def bending_frequencies(EI: float, rho_a: float, length: float, support: str = "propped", n: int = 1):
    """Euler-Bernoulli bending frequencies [Hz], (beta L)^2 / (2 pi L^2) sqrt(EI / (rho A)), of the
    clamped-free (``cantilever``) or clamped-pinned (``propped``) beam."""
    table = {"cantilever": CANTILEVER_BETA_L, "propped": PROPPED_BETA_L}
    if support not in table:
        raise ValueError(f"support: must be 'cantilever' or 'propped', got {support!r}")
    bl = np.asarray(table[support][:n])
    return bl**2 / (2.0 * math.pi * length**2) * math.sqrt(EI / rho_a)


def axial_frequencies(E: float, rho: float, length: float, n: int = 1):
    """Clamped-free bar frequencies [Hz]: (2k - 1) sqrt(E / rho) / (4 L)."""
    k = np.arange(1, n + 1)
    return (2 * k - 1) * math.sqrt(E / rho) / (4.0 * length)


def propped_mode_tip_slope(rho_a: float, length: float, n_points: int = 4001) -> float:
    """|phi'(L)| [rad per unit modal coordinate] of the first clamped-pinned mode normalised to unit
    modal mass (integral of rho A phi^2 = 1): phi = cosh bx - cos bx - s (sinh bx - sin bx)."""
    b = PROPPED_BETA_L[0] / length
    bl = PROPPED_BETA_L[0]
    s = (math.cosh(bl) - math.cos(bl)) / (math.sinh(bl) - math.sin(bl))
    x = np.linspace(0.0, length, n_points)
    phi = np.cosh(b * x) - np.cos(b * x) - s * (np.sinh(b * x) - np.sin(b * x))
    y = rho_a * phi**2
    mass = float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x)))
    slope = b * (math.sinh(bl) + math.sin(bl) - s * (math.cosh(bl) - math.cos(bl)))
    return abs(slope) / math.sqrt(mass)


def axial_mode_tip_amplitude(rho_a: float, length: float) -> float:
    """Tip amplitude of any clamped-free axial mode at unit modal mass: sqrt(2 / (rho A L))."""
    return math.sqrt(2.0 / (rho_a * length))


def negative_damping_growth_rate(
    normal_force: float, friction_slope: float, tangential_amplitude: float, omega: float, beta: float = 0.0
) -> float:
    """Growth rate [s-1] of a mode from the falling friction law: -N mu'(V) a^2 / 2 - beta omega^2 / 2,
    with a the mode's tangential amplitude at the contact at unit modal mass, mu' = d mu / d v_r at the
    sliding speed [s mm-1] and beta the stiffness-proportional damping [s]. Negative: the mode decays."""
    return -0.5 * normal_force * friction_slope * tangential_amplitude**2 - 0.5 * beta * omega**2


def slip_distance(duration: float, speed: float) -> float:
    """Disc surface travel [mm] during ``duration`` [s] at ``speed`` [mm s-1]: what a stick (or micro-slip)
    phase of that duration must absorb elastically."""
    return duration * speed


def elastic_stick_capacity(mu_s: float, normal_force: float, tangential_stiffness: float) -> float:
    """Largest tangential deflection [mm] a stuck contact can hold before slipping: mu_s N / k_t."""
    return mu_s * normal_force / tangential_stiffness


def stick_duration_limit(mu_s: float, normal_force: float, tangential_stiffness: float, speed: float):
    """Longest quasi-static stick [s] at disc speed V: mu_s N / (k_t V)."""
    return elastic_stick_capacity(mu_s, normal_force, tangential_stiffness) / speed


def tilted_contact_normal_force(n0: float, angle_deg: float, reading: str) -> float:
    """Static contact force [N] at a contact angle, under the two readings of the paper's "the normal load
    decrease[s] due to change it to a component":

    * ``beam_tilted``: the beam (and gravity's share on the prop) is tilted against the disc normal, the
      contact takes the component N0 cos(a) - the paper's "decrease";
    * ``normal_tilted``: the beam stays horizontal, the disc normal at the contact is tilted by a; with the
      beam far stiffer axially than in bending, the contact force must still carry the prop's vertical share,
      N0 / cos(a) - an increase (the project's geometry).
    """
    a = math.radians(angle_deg)
    if reading == "beam_tilted":
        return n0 * math.cos(a)
    if reading == "normal_tilted":
        return n0 / math.cos(a)
    raise ValueError(f"reading: must be 'beam_tilted' or 'normal_tilted', got {reading!r}")


def drop_overshoot(static_value: float) -> float:
    """Peak of an undamped linear response to a suddenly applied constant load: twice the static value."""
    return 2.0 * static_value
