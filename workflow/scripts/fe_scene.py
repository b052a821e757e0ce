"""Run one beam-on-disc scene and write results/fe/<scene>.nc."""

from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import INTERPRETATION, run_scene, scene_dataset, scene_mapping
from stickslip.io.progress import step_callback

from fe_common import log_to, write_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
name = snakemake.wildcards.scene  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
mapping = scene_mapping(cfg, name)
r, m, scene = run_scene(mapping, friction, progress=step_callback(f"fe_scene {name}: time steps"))
print(f"{name}: dt={r.dt:.4g} s, steps={r.n_steps}, cpu={r.cpu_time:.1f} s, fractions={r.fractions()}")
ds = scene_dataset(name, mapping, r, m, scene)
write_dataset(
    ds,
    snakemake.output[0],
    scene=mapping,
    interpretation=INTERPRETATION,  # noqa: F821
    method={
        "integrator": "central_difference",
        "contact": scene.law.method,
        "dt": r.dt,
        "dt_crit": r.dt_crit,
    },
)
