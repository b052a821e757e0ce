"""Paper Eq. 6, the frequency-amplitude curve of Fig. 4, as printed and in its dimensionally correct form.

Printed:  A(w) = |F / sqrt((K - w^2)^2 + c w^2)|      (M missing, c multiplies w^2 not (c w)^2)
Correct:  A(w) = F / sqrt((K - M w^2)^2 + (C w)^2)     (steady response of M x'' + C x' + K x = F sin wt)

F is "the friction force"; we take F = mu_s N (the static friction limit, 5 N at the baseline) - the paper
does not say which value it used. w is the angular frequency [rad/s]; figures plot f = w / 2 pi [Hz].
Both maxima have closed forms (``printed_peak``, ``correct_peak``).
"""

from __future__ import annotations

import math

import numpy as np


def amplitude_printed(omega, force: float, stiffness: float, damping: float):
    omega = np.asarray(omega, dtype=float)
    return np.abs(force / np.sqrt((stiffness - omega**2) ** 2 + damping * omega**2))


def amplitude_correct(omega, force: float, stiffness: float, damping: float, mass: float):
    omega = np.asarray(omega, dtype=float)
    return np.abs(force / np.sqrt((stiffness - mass * omega**2) ** 2 + (damping * omega) ** 2))


def printed_peak(force: float, stiffness: float, damping: float) -> tuple[float, float]:
    """(f_peak [Hz], A_peak) of the printed curve.

    d/d(w^2) of (K - w^2)^2 + c w^2 vanishes at w^2 = K - c/2 (w = 0 if that is < 0).
    """
    w2 = max(stiffness - 0.5 * damping, 0.0)
    return math.sqrt(w2) / (2 * math.pi), float(amplitude_printed(math.sqrt(w2), force, stiffness, damping))


def correct_peak(force: float, stiffness: float, damping: float, mass: float) -> tuple[float, float]:
    """(f_peak [Hz], A_peak) of the 1-DOF curve.

    Resonance at w^2 = K/M - C^2/(2 M^2); no peak (w = 0, A = F/K) if that is < 0.
    """
    w2 = max(stiffness / mass - damping**2 / (2 * mass**2), 0.0)
    return math.sqrt(w2) / (2 * math.pi), float(
        amplitude_correct(math.sqrt(w2), force, stiffness, damping, mass)
    )
