"""Decisions that rest on digits below the numerical noise: every claimed metric moved to the end of its
perturbation-ensemble range, every claim evaluated again. A claim decided on the base values (reproduced or
deviates) must keep its decision or become undecided, never the opposite. The build runs this beside the pin
check (rule ``claims_check``), on the full configuration's own results."""

from __future__ import annotations

import functools
import warnings
from collections.abc import Callable

import numpy as np

from .evaluate import evaluate_all
from .rows import Claim
from .verdicts import DECIDED


def moved_opener(read: Callable, reduce: Callable) -> Callable:
    """``open_dataset`` whose datasets have every variable with an ensemble (``<name>_ensemble``) replaced
    by ``reduce`` over the members (each dataset read once through ``read`` and moved once)."""
    opened = {}

    def open_dataset(path):
        if path not in opened:
            ds = read(path)
            names = [v for v in ds.data_vars if f"{v}_ensemble" in ds]
            with warnings.catch_warnings():  # a metric NaN in every member stays NaN
                warnings.simplefilter("ignore", RuntimeWarning)
                values = {
                    n: (ds[n].dims, reduce(ds[f"{n}_ensemble"].values, axis=0), ds[n].attrs) for n in names
                }
            opened[path] = ds.assign(values)  # one assignment: each one re-aligns the dataset
        return opened[path]

    return open_dataset


def flipped_decisions(claims: list[Claim], readings: list[str], read: Callable) -> list[str]:
    """Claims (with reading) whose decision flips at the ensemble minimum or maximum; ``read(path)`` opens a
    dataset (cached by the caller or not: each path is read once per pass)."""
    cached = functools.cache(read)
    first = functools.partial(np.take, indices=0)  # the base run (member 0): the claims table's own numbers
    base = {
        (r.claim, r.reading): r.status for r in evaluate_all(claims, readings, moved_opener(cached, first))
    }
    flipped = []
    for reduce in (np.nanmin, np.nanmax):
        for r in evaluate_all(claims, readings, moved_opener(cached, reduce)):
            before = base[(r.claim, r.reading)]
            if before in DECIDED and r.status not in (before, "indistinguishable"):
                flipped.append(
                    f"{r.claim} [{r.reading}] {before} -> {r.status} at the ensemble {reduce.__name__}"
                )
    return flipped
