"""Every paper scene under one FE reading -> results/fe/<reading>/<scene>.nc (each with its perturbation
ensemble), plus the cross-scene ratios."""

from pathlib import Path

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import (
    INTERPRETATION,
    cross_scene_dataset,
    effective_fe_config,
    scene_dataset,
    scene_mapping,
)

from fe_common import log_to, write_dataset

log_to(snakemake)  # noqa: F821
cfg = effective_fe_config(snakemake.params.config)  # noqa: F821
reading = snakemake.wildcards.fe_reading  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
spec = EnsembleSpec.from_mapping(snakemake.params.ensemble)  # noqa: F821
built = {}
for path in snakemake.output.scenes:  # noqa: F821
    name = Path(path).stem
    mapping = scene_mapping(cfg, name, reading)
    ds = ensemble_dataset(lambda mp, n=name: scene_dataset(mp, friction, n), mapping, spec)
    ds.attrs["fe_reading"] = reading
    print(f"{reading}/{name}: {ds.attrs['method']}, cpu={float(ds['cpu_time']):.2f} s", flush=True)
    write_dataset(ds, path, scene=mapping, interpretation=INTERPRETATION, method={"fe_reading": reading})
    built[name] = ds
cross = cross_scene_dataset(built, cfg["cross_scene"])
write_dataset(
    cross,
    snakemake.output.cross,  # noqa: F821
    scene=dict(cfg["cross_scene"]),
    interpretation=INTERPRETATION,
    method={"kind": "ratio", "fe_reading": reading},
)
