"""Run one beam-on-disc scene and write results/fe/<scene>.nc, with its perturbation ensemble."""

from stickslip.ensemble import EnsembleSpec, ensemble_dataset
from stickslip.fe.params import FrictionTable
from stickslip.fe.pipeline import INTERPRETATION, run_scene, scene_dataset, scene_mapping

from fe_common import log_to, write_dataset

log_to(snakemake)  # noqa: F821
cfg = snakemake.config["fe"]  # noqa: F821
name = snakemake.wildcards.scene  # noqa: F821
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
mapping = scene_mapping(cfg, name)
runs = []


def build(scene_mapping_):
    r, m, scene = run_scene(scene_mapping_, friction)
    print(f"{name}: dt={r.dt:.4g} s, steps={r.n_steps}, cpu={r.cpu_time:.1f} s, fractions={r.fractions()}")
    runs.append((r, scene))
    return scene_dataset(name, scene_mapping_, r, m, scene)


ds = ensemble_dataset(build, mapping, EnsembleSpec.from_mapping(snakemake.params.ensemble))  # noqa: F821
r, scene = runs[0]
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
