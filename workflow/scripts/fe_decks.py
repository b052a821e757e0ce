"""Every Section 9-12 scene as an ABAQUS/Explicit input deck -> results/fe/inp/<scene>.inp."""

from stickslip.fe.abaqus_deck import scene_deck
from stickslip.fe.params import FrictionTable
from stickslip.io.progress import log_to_file
from stickslip.io.text_files import write_text_atomic
from stickslip.studies.fe_config import scene_mapping

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
cfg = snakemake.params.config  # noqa: F821  (every scene resolved, and the comparison section)
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
nx, ny = cfg["comparison"]["mesh"]
for scene, path in zip(snakemake.params.scenes, snakemake.output.decks, strict=True):  # noqa: F821
    write_text_atomic(path, scene_deck(scene, scene_mapping(cfg, scene), friction, nx, ny))
    print(f"{scene}: {path}")
