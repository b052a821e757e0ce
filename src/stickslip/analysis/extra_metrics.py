"""Scalars some claims need beyond the limit-cycle table.

Early vs late amplitude (decelerating belt, Fig. 15), the friction coefficient range along the solution
(Fig. 17), the final speed (Fig. 16 settles).
"""

from __future__ import annotations

import numpy as np

from .friction_curve import friction_along_solution


def extra_metrics(t, x, v, vb, phase, friction, normal_force: float) -> dict[str, float]:
    """Values of the registered metrics early/late (velocity) amplitude, final speed, the smallest slip
    friction coefficient and the largest relative speed (units and names: ``metrics.METRICS``)."""
    t, x, v, vb = (np.asarray(a, dtype=float) for a in (t, x, v, vb))
    # Halves of the run, or of the deceleration phase when the belt stops: comparing "before" with "after the
    # belt has stopped" would make any decay claim true by construction.
    stopped = vb <= 0.0
    t_ref = float(t[np.argmax(stopped)]) if stopped.any() else float(t[-1])
    half = t <= 0.5 * t_ref
    late = ~half & (t <= t_ref)
    _, mu_slip = friction_along_solution(v, vb, phase, friction, normal_force)
    with np.errstate(all="ignore"):
        return {
            "early_amplitude": float(np.ptp(x[half])),
            "late_amplitude": float(np.ptp(x[late])),
            "early_velocity_amplitude": float(np.ptp(v[half])),
            "late_velocity_amplitude": float(np.ptp(v[late])),
            "final_speed": float(abs(v[-1])),
            "friction_min_slip": float(np.min(mu_slip)) if mu_slip.size else np.nan,
            "relative_speed_max": float(np.max(np.abs(v - vb))),
        }
