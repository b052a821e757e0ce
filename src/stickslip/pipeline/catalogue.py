"""Where the 1-DOF runs' datasets live, defined once, and the way back from a dataset to its run.

A rule, a claim or a notebook names a dataset by its path; the catalogue is built forward from the config
(every scene x reading x method), so a path is looked up, never parsed: a path that is not in the catalogue
is not a 1-DOF run, whatever it looks like.
"""

from __future__ import annotations

from dataclasses import dataclass


def onedof_dataset(scene: str, reading: str, method: str) -> str:
    """The dataset of one 1-DOF run (rule ``simulate_onedof_<scene>``)."""
    return f"results/onedof/{scene}/{reading}/{method}.nc"


def sweep_dataset(sweep: str, reading: str, dense: bool = False) -> str:
    """The dataset of one sweep for one reading, at the paper's values or dense (rule ``onedof_sweeps``)."""
    return f"results/onedof/sweeps/{sweep}{'_dense' if dense else ''}/{reading}.nc"


@dataclass(frozen=True)
class OnedofRun:
    scene: str
    reading: str
    method: str

    @property
    def path(self) -> str:
        return onedof_dataset(self.scene, self.reading, self.method)


def onedof_catalogue(onedof: dict) -> dict[str, OnedofRun]:
    """dataset path -> run, for every scene, reading and method of the ``onedof`` config section."""
    runs = (
        OnedofRun(scene, reading, method)
        for scene in onedof["scenes"]
        for reading in onedof["readings"]
        for method in onedof["methods"]
    )
    return {run.path: run for run in runs}
