"""Every Section 9-12 scene as an ABAQUS/Explicit input deck -> results/fe/inp/<scene>.inp, and its CalculiX
variant -> results/fe/inp/<scene>_ccx.inp."""

from stickslip.fe.abaqus_deck import scene_deck
from stickslip.fe.ccx_deck import CCX_MAX_INCREMENT, CCX_T_END, ccx_scene_deck
from stickslip.fe.params import FrictionTable
from stickslip.io.progress import log_to_file
from stickslip.io.text_files import write_text_atomic
from stickslip.schema.fe import FeJob
from stickslip.studies.fe_config import as_mapping

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
job = FeJob.model_validate(snakemake.params.config)  # noqa: F821  (every scene resolved, the comparison)
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
nx, ny = job.comparison.mesh
out = snakemake.output  # noqa: F821
for scene, path, ccx_path in zip(snakemake.params.scenes, out.decks, out.ccx_decks, strict=True):  # noqa: F821
    mapping = as_mapping(job.scenes[scene])
    write_text_atomic(path, scene_deck(scene, mapping, friction, nx, ny))
    ccx = ccx_scene_deck(scene, mapping, nx, ny, t_end=CCX_T_END, dt=CCX_MAX_INCREMENT)
    write_text_atomic(ccx_path, ccx)
    print(f"{scene}: {path}, {ccx_path}")
