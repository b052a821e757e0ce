"""Sweeps, convergence and stability studies, continuum increments -> results/fe/*.nc (one job)."""

from pathlib import Path

from stickslip.fe.comparison import increments_dataset
from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import (
    INTERPRETATION,
    convergence_dataset,
    scene_mapping,
    stability_dataset,
    sweep_dataset,
)

from fe_common import log_to, write_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.params.config["fe"]  # noqa: F821
out = snakemake.output  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
for path in out.sweeps:
    name = Path(path).stem
    ds = sweep_dataset(cfg, name, friction)
    method = {"integrator": "central_difference", "sweep": name}
    write_dataset(ds, path, scene=dict(cfg["sweeps"][name]), interpretation=INTERPRETATION, method=method)
    print(f"sweep {name} written", flush=True)
for kind, build in (("convergence", convergence_dataset), ("stability", stability_dataset)):
    ds = build(cfg, friction)
    write_dataset(ds, out[kind], scene=dict(cfg[kind]), interpretation=INTERPRETATION, method={"study": kind})
    print(f"{kind} written", flush=True)
inc = cfg["increments"]
ds = increments_dataset(
    scene_mapping(cfg, inc["base"]), [tuple(m) for m in inc["meshes"]], inc["safety_factors"], inc["betas"]
)
write_dataset(ds, out.increments, scene=dict(inc), interpretation=INTERPRETATION, method={"kind": "eigen"})
