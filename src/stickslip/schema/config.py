"""The whole config as one typed object: ``PipelineConfig`` (every section's model, the cross-section
references and the cost guard) and the JSON schema generated from it.

``stickslip.pipeline.config.validate_config`` validates the merged config against ``PipelineConfig`` and
then resolves what a model alone cannot (solver settings, files). The JSON schema in
``workflow/schemas/config.schema.json`` is generated from these models (``python -m stickslip.schema
--write``; a test checks it is current), never written by hand.
"""

from __future__ import annotations

import json

from pydantic import Field, model_validator

from .base import Section, check_refs, needs_switch
from .dense_map import DenseMaps
from .fe import Fe
from .inverse import Inverse
from .methods import MethodsStudy
from .onedof import Claims, Ensemble, Notebook, Onedof, merged_run_lengths
from .validation import Validation

# -- the whole config ----------------------------------------------------------------------------------------
#: What one build may ask for before ``allow_expensive: true`` must say it is meant. The default config's
#: largest study stores 6.4e6 samples (the speed-damping dense map) and one run at most 4.0e4
#: (``estimated_costs``); the limits sit ~50-80x above, below what would exhaust a 24 GiB machine (8 bytes a
#: sample, several arrays a run).
MAX_SAMPLES_PER_RUN = 2_000_000
MAX_SAMPLES_PER_STUDY = 500_000_000
#: Perturbation-ensemble seeds a run may draw (each one more run of it): the default config draws 2; the
#: limit sits 50x above, as the sample limits do. The command line and ``stickslip.api`` check it before
#: any work (``api.check_ensemble_cost``).
MAX_ENSEMBLE_SEEDS = 100
#: Largest beam mesh (elements) or continuum mesh (cells) without ``allow_expensive`` (the paper: 100 x 1).
MAX_FE_ELEMENTS = 20_000


def stored_samples(t_end: float, output_dt: float) -> int:
    """Samples a run of ``t_end`` stores every ``output_dt`` (both ends included): what the guard counts."""
    return int(t_end / output_dt) + 1


def estimated_costs(cfg: PipelineConfig) -> list[tuple[str, str, float, float]]:
    """(key, what, estimate, limit) of every study whose size the config sets, in stored samples (1-DOF) or
    mesh elements (FE). Cheap: sizes only, nothing is allocated."""
    import math

    onedof = cfg.onedof
    out = []
    for name, scene in onedof.scenes.items():
        run, _ = merged_run_lengths([("d", onedof.defaults), ("s", scene)])
        for rname, reading in onedof.readings.items():
            dt = reading.output_dt or run["output_dt"]
            key = f"onedof.scenes.{name} (reading {rname})"
            out.append((key, "samples per run", stored_samples(run["t_end"], dt), MAX_SAMPLES_PER_RUN))
    for name, sweep in onedof.sweeps.items():
        scene = onedof.scenes.get(sweep.scene or onedof.baseline.scene)
        run, _ = merged_run_lengths([("d", onedof.defaults), ("s", scene)])
        points = (len(sweep.values) + sweep.dense.num) * len(cfg.claims.readings)
        per_run = stored_samples(run["t_end"], run["output_dt"])
        out.append((f"onedof.sweeps.{name}.dense.num", "samples", points * per_run, MAX_SAMPLES_PER_STUDY))
    for name, m in cfg.dense_map.maps.items():
        scene = onedof.scenes.get(m.scene)
        run, _ = merged_run_lengths([("d", onedof.defaults), ("s", scene), ("m", m)])
        points = math.prod(a.size for a in m.axes)
        per_run = stored_samples(run["t_end"], run["output_dt"])
        out.append((f"dense_map.maps.{name}.axes", "samples", points * per_run, MAX_SAMPLES_PER_STUDY))
    if onedof.critical_speed is not None:
        cs = onedof.critical_speed
        per_run = stored_samples(cs.t_end, onedof.defaults.output_dt)
        out.append(("onedof.critical_speed.num", "samples", cs.num * per_run, MAX_SAMPLES_PER_STUDY))
    fe = cfg.fe
    beams = [("fe.defaults", fe.defaults.beam)]
    beams += [
        (f"fe.{section}.{n}", sc.beam)
        for section in ("scenes", "readings")
        for n, sc in getattr(fe, section).items()
    ]
    for key, beam in beams:
        if beam is not None and beam.n_elements is not None:
            out.append((f"{key}.beam.n_elements", "elements", beam.n_elements, MAX_FE_ELEMENTS))
    out.append(("fe.convergence.n_elements", "elements", max(fe.convergence.n_elements), MAX_FE_ELEMENTS))
    for i, (nx, ny) in enumerate([fe.comparison.mesh] + list(fe.increments.meshes)):
        key = "fe.comparison.mesh" if i == 0 else f"fe.increments.meshes[{i - 1}]"
        out.append((key, "cells", nx * ny, MAX_FE_ELEMENTS))
    return out


class PipelineConfig(Section):
    """The merged config Snakemake builds from config/*.yaml (and any --configfile)."""

    onedof: Onedof
    claims: Claims
    notebooks: dict[str, Notebook]
    ensemble: Ensemble | None = None
    dense_map: DenseMaps
    methods_study: MethodsStudy
    fe: Fe
    fe_long_runs: bool = Field(False, description="run the paper's windows (fe.long_runs), not short ones")
    inverse: Inverse
    validation: Validation
    allow_expensive: bool = Field(
        False, description="true: build even a study larger than the cost guard's limits (estimated_costs)"
    )

    @model_validator(mode="after")
    def within_cost_limits(self):
        """Every study's size below its limit, unless ``allow_expensive: true`` (the estimate is reported)."""
        if not self.allow_expensive:
            for key, what, estimate, limit in estimated_costs(self):
                if estimate > limit:
                    raise ValueError(
                        f"{key}: an estimated {estimate:.3g} {what}, more than the limit {limit:.3g}; set "
                        "allow_expensive: true to build it anyway"
                    )
        return self

    @model_validator(mode="after")
    def sections_refer_to_each_other(self):
        """Claims readings, dense maps and notebooks name existing 1-DOF entries."""
        onedof = self.onedof
        check_refs([("claims.readings", r) for r in self.claims.readings], onedof.readings, "onedof.readings")
        for name, m in self.dense_map.maps.items():
            key = f"dense_map.maps.{name}"
            check_refs([(f"{key}.scene", m.scene)], onedof.scenes, "onedof.scenes")
            check_refs([(f"{key}.reading", m.reading)], onedof.readings, "onedof.readings")
            check_refs([(f"{key}.method", m.method)], onedof.methods, "onedof.methods")
            needs_switch(key, m.law, m.method, onedof.methods)
        for name, fig in self.inverse.figures.items():
            key = f"inverse.figures.{name}"
            check_refs([(f"{key}.scene", fig.scene)] if fig.scene else [], onedof.scenes, "onedof.scenes")
            check_refs([(f"{key}.sweep", fig.sweep)] if fig.sweep else [], onedof.sweeps, "onedof.sweeps")
        for name, nb in self.notebooks.items():
            key = f"notebooks.{name}"
            check_refs([(f"{key}.figures", f) for f in nb.figures or []], onedof.figures, "onedof.figures")
            figs = [(f"{key}.sweep_figures", f) for f in nb.sweep_figures or []]
            check_refs(figs, onedof.sweep_figures, "onedof.sweep_figures")
        return self


def json_schema() -> dict:
    """The JSON schema of ``PipelineConfig`` (what ``workflow/schemas/config.schema.json`` holds)."""
    schema = PipelineConfig.model_json_schema()
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    return schema


def schema_text() -> str:
    return json.dumps(json_schema(), indent=1, sort_keys=True) + "\n"
