"""Cross-scene ratios (e.g. penalty over kinematic velocities) -> results/fe/cross_scene.nc."""

from pathlib import Path

import xarray as xr

from stickslip.fe.pipeline import INTERPRETATION, cross_scene_dataset

from fe_common import log_to, write_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
dss = {Path(p).stem: xr.load_dataset(p) for p in snakemake.input}  # noqa: F821
ds = cross_scene_dataset(dss, cfg["cross_scene"])
print(ds)
write_dataset(
    ds,
    snakemake.output[0],
    scene=dict(cfg["cross_scene"]),
    interpretation=INTERPRETATION,  # noqa: F821
    method={"kind": "ratio"},
)
