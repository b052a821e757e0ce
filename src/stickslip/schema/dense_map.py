"""The ``dense_map`` section (``config/dense_map.yaml``): the dense parameter maps."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, field_validator, model_validator

from .base import DEFAULT_MAX_CHUNKS, Finite, Names, Open, Section, belt_parameter, linked_parameters
from .onedof import Law, OnedofJob, RunLengths

#: The metrics a dense map's figure shows unless its ``plot`` names others (one panel each).
DEFAULT_PLOT = ("amplitude_peak_to_peak", "frequency_peaks", "stick_fraction")


class MapAxis(Section):
    """Values listed, or ``num`` points from ``start`` to ``stop`` (linear or log ``spacing``)."""

    name: str
    values: Annotated[list[Finite], Field(min_length=1)] | None = None
    start: Finite | None = None
    stop: Finite | None = None
    num: Annotated[int, Field(ge=1)] | None = None
    spacing: Literal["linear", "log"] = "linear"
    units: str = ""
    long_name: str = ""
    linked: dict[str, Finite] = Field({}, description="parameters set to factor x the swept value")

    _name = field_validator("name")(belt_parameter)
    _linked = field_validator("linked")(linked_parameters)

    @model_validator(mode="after")
    def values_or_range(self):
        if self.values is None:
            missing = [k for k in ("start", "stop", "num") if getattr(self, k) is None]
            if missing:
                raise ValueError(f"{missing[0]}: missing (give either values or start, stop, num)")
            if self.num > 1 and not self.start < self.stop:
                raise ValueError(f"start < stop needed, got {self.start!r}, {self.stop!r}")
            if self.spacing == "log" and not (self.start > 0 and self.stop > 0):
                raise ValueError(
                    f"log spacing needs start > 0 and stop > 0, got {self.start!r}, {self.stop!r}"
                )
        return self

    @property
    def size(self) -> int:
        return len(self.values) if self.values is not None else self.num


class DenseMapEntry(RunLengths):
    title: str | None = None
    scene: str
    reading: str
    method: str
    law: Law | None = None
    chunk_size: Annotated[int, Field(ge=1)] | None = Field(None, description="default: dense_map.chunk_size")
    plot: Names = list(DEFAULT_PLOT)
    axes: Annotated[list[MapAxis], Field(min_length=1)]

    @model_validator(mode="after")
    def each_parameter_once(self):
        names = [a.name for a in self.axes]
        for i, name in enumerate(names):
            if name in names[:i]:
                raise ValueError(f"axes[{i}].name: {name!r} is swept twice")
        return self


class Resources(Open):
    mem_mb: Annotated[int, Field(ge=1)] | None = None
    runtime: Annotated[int, Field(ge=1)] | None = None
    cpus_per_task: Annotated[int, Field(ge=1)] | None = None


class DenseMapResources(Section):
    dense_map_chunk: Resources | None = None
    dense_map_merge: Resources | None = None
    dense_map_figure: Resources | None = None


class DenseMaps(Section):
    chunk_size: Annotated[int, Field(ge=1)]
    max_chunks: Annotated[int, Field(ge=1)] | None = None
    maps: Annotated[dict[str, DenseMapEntry], Field(min_length=1)]
    resources: DenseMapResources

    @model_validator(mode="after")
    def chunks_within_limit(self):
        """A chunk size that would make more jobs than ``max_chunks`` (default 2000) is an error."""
        import math

        limit = self.max_chunks or DEFAULT_MAX_CHUNKS
        for name, m in self.maps.items():
            points = math.prod(a.size for a in m.axes)
            size = m.chunk_size or self.chunk_size
            key = f"dense_map.maps.{name}.chunk_size" if m.chunk_size else "dense_map.chunk_size"
            jobs = math.ceil(points / size)
            if jobs > limit:
                raise ValueError(
                    f"{key}: {size} points per chunk make {jobs} jobs for {points} points, more than "
                    f"max_chunks = {limit}; use at least {math.ceil(points / limit)} points per chunk"
                )
        return self


class DenseMapJob(OnedofJob):
    """A dense-map job's params mapping: the 1-DOF run it starts from and the section with only its map."""

    dense_map: DenseMaps
