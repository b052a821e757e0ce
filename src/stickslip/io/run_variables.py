"""The variables of a 1-DOF run dataset, without xarray: the workflow checks claims against them at parse
time, and importing the netCDF writer there would cost every no-op half a second."""

from __future__ import annotations

#: Time series and solver scalars of every run dataset (``trajectory_dataset``), beside its metrics.
RUN_SERIES = ("displacement", "velocity", "belt_velocity", "relative_velocity", "phase")
RUN_SOLVER = ("solver_status", "solver_rhs_evaluations", "solver_steps", "solver_events", "solver_cpu_time")
RUN_SEGMENTS = ("segment_start", "segment_end", "segment_phase")


def run_dataset_variables() -> frozenset[str]:
    """Every variable a 1-DOF run dataset may hold: what a claim on such a dataset may name."""
    from ..analysis.metrics import METRICS

    return frozenset(RUN_SERIES + RUN_SOLVER + RUN_SEGMENTS) | frozenset(METRICS)
