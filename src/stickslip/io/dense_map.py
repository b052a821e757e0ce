"""Dense maps from the config: (run settings, axes, chunking) of one map. No science.

Used by workflow/rules/dense_map.smk at parse time (so every error appears before any job starts, naming
the config key at fault) and by the dense_map_* scripts.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from ..analysis.sweep import SweepAxis, axes_from_config, check_axes, check_chunking, grid_size, run_points
from ..model.laws import FrictionLaw, law_from_config
from ..model.params import ParameterError
from .scenes import RunSpec, run_spec

RUN_OVERRIDES = ("t_end", "output_dt", "transient", "count_window")
DEFAULT_MAX_CHUNKS = 2000


@dataclass(frozen=True)
class DenseMap:
    name: str
    spec: RunSpec
    """Base run: scene parameters, reading (friction variant, sigma), solver and run lengths."""
    axes: list[SweepAxis]
    chunk_size: int
    chunks: int
    title: str
    plot: tuple
    law: FrictionLaw | None = None
    """Any friction law replacing the reading's (solved with the switch solver); None: the reading's law."""

    @property
    def points(self) -> int:
        return grid_size(self.axes)

    def run(self, points: list[dict], progress=None) -> dict:
        """Metric arrays of the given grid points with this map's base run (run_points)."""
        s = self.spec
        return run_points(
            s.params,
            s.variant,
            points,
            s.solver(),
            s.t_end,
            s.t_eval,
            s.transient,
            s.count_window,
            progress=progress,
            law=self.law,
        )

    def method_attrs(self) -> dict:
        return {
            "name": self.spec.method,
            **self.spec.solver_settings,
            "chunk_size": self.chunk_size,
            "chunks": self.chunks,
            "grid_points": self.points,
            "t_end": self.spec.t_end,
            "output_dt": self.spec.output_dt,
            "transient": self.spec.transient,
            "count_window": self.spec.count_window,
        }

    def scene_attrs(self) -> dict:
        base = self.spec.scene_attrs()
        for axis in self.axes:  # a swept parameter's base value is not used: point to the coordinate
            for name in (axis.name, *axis.linked):
                base[name] = f"swept (coordinate {axis.name})"
        if self.law is not None:
            base["friction_law"] = repr(self.law)
        return {
            **base,
            "map": self.name,
            "swept": ", ".join(
                f"{a.name} ({len(a.values)} values, {min(a.values):g}..{max(a.values):g})" for a in self.axes
            ),
        }


def dense_map(config: dict, name: str) -> DenseMap:
    section = config.get("dense_map", {})
    key = f"dense_map.maps.{name}"
    cfg = section.get("maps", {}).get(name)
    if cfg is None:
        raise ParameterError(f"{key}: no such map (known: {sorted(section.get('maps', {}))})")
    try:
        spec = run_spec(config, cfg["scene"], cfg["reading"], cfg["method"])
    except ParameterError as exc:
        raise ParameterError(f"{key} (scene/reading/method): {exc}") from None
    law = None
    if "law" in cfg:
        law = law_from_config(cfg["law"], key=f"{key}.law")
        if spec.solver_settings.get("solver") != "switch":
            raise ParameterError(
                f"{key}.method: a map with a friction law needs a method whose solver is 'switch' (the exact "
                f"solver handles the readings' affine laws only), got {cfg['method']!r}"
            )
    overrides = {k: float(cfg[k]) for k in RUN_OVERRIDES if k in cfg}
    spec = dataclasses.replace(spec, **overrides)
    axes = axes_from_config(cfg.get("axes"), f"{key}.axes")
    check_axes(spec.params, axes, f"{key}.axes")
    chunk_key = f"{key}.chunk_size" if "chunk_size" in cfg else "dense_map.chunk_size"
    chunk_size = cfg.get("chunk_size", section.get("chunk_size"))
    chunks = check_chunking(axes, chunk_size, chunk_key, section.get("max_chunks", DEFAULT_MAX_CHUNKS))
    plot = tuple(cfg.get("plot", ("amplitude_peak_to_peak", "frequency_peaks", "stick_fraction")))
    return DenseMap(
        name=name,
        spec=spec,
        axes=axes,
        chunk_size=chunk_size,
        chunks=chunks,
        title=str(cfg.get("title", name)),
        plot=plot,
        law=law,
    )
