"""Increments of the continuum strip for 0.65 s (the paper's ABAQUS banner) -> continuum_increments.nc."""

from stickslip.fe.comparison import increments_dataset
from stickslip.fe.pipeline import INTERPRETATION, scene_mapping

from fe_common import log_to, write_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
inc = cfg["increments"]
mapping = scene_mapping(cfg, inc["base"])
ds = increments_dataset(mapping, [tuple(m) for m in inc["meshes"]], inc["safety_factors"], inc["betas"])
print(ds)
write_dataset(
    ds, snakemake.output[0], scene=dict(inc), interpretation=INTERPRETATION, method={"kind": "eigen"}
)  # noqa: F821
