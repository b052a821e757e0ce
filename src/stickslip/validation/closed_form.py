"""Textbook closed form: the stick-slip cycle of an undamped mass on a belt with Coulomb friction.

M x'' + K x = F, belt speed V_b > 0, friction mu_s N at rest and mu_k N in slip (mu_s > mu_k), no damping.
Stick ends where the spring force reaches the static limit, x_s = mu_s N / K. The slip that follows (v < V_b,
friction +mu_k N) is harmonic about x_k = mu_k N / K, starting at x_s - x_k = Delta = (mu_s - mu_k) N / K with
v = V_b:

    x - x_k = A cos(w tau + phi),   A = sqrt(Delta^2 + (V_b / w)^2),   w = sqrt(K / M),
    tan(phi) = -V_b / (w Delta)

It returns to v = V_b at the mirror point x_k - Delta after tau_slip = (pi + 2 arctan(V_b / (w Delta))) / w,
then sticks for 2 Delta / V_b (|K (x_k - Delta)| <= mu_s N holds since mu_k <= mu_s). The cycle reaches
x_k +- A. (Den Hartog; e.g. Popp & Stelter 1990, Phil. Trans. R. Soc. A 332.)
"""

from __future__ import annotations

import math

from ..model.params import ParameterError


def coulomb_cycle(
    mass: float, stiffness: float, normal_force: float, belt_velocity: float, mu_s: float, mu_k: float
) -> dict:
    """Period, stick/slip durations, release and onset positions, extrema of the undamped Coulomb cycle."""
    if not mu_s > mu_k > 0:
        raise ParameterError(f"mu_k: the classical cycle needs mu_s > mu_k > 0, got mu_s={mu_s}, mu_k={mu_k}")
    if not belt_velocity > 0:
        raise ParameterError(f"belt_velocity: must be > 0, got {belt_velocity}")
    w = math.sqrt(stiffness / mass)
    x_k = mu_k * normal_force / stiffness
    delta = (mu_s - mu_k) * normal_force / stiffness
    amplitude = math.hypot(delta, belt_velocity / w)
    slip = (math.pi + 2.0 * math.atan(belt_velocity / (w * delta))) / w
    stick = 2.0 * delta / belt_velocity
    return {
        "period": stick + slip,
        "stick_duration": stick,
        "slip_duration": slip,
        "release_position": x_k + delta,
        "onset_position": x_k - delta,
        "x_max": x_k + amplitude,
        "x_min": x_k - amplitude,
    }
