"""Snakemake script: work-precision data of every method on one scene."""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from methods_common import expand_methods, records_dataset, run_scene, scene_model, write  # noqa: E402

cfg = snakemake.params.study  # noqa: F821
scene = snakemake.wildcards.scene  # noqa: F821
model = scene_model(cfg, scene)
records, ref, ref_cycle, paper = run_scene(cfg, model, cfg["t_end"], expand_methods(cfg["methods"]))
ds = records_dataset(records)
ds["cpu_ratio_to_paper"] = (
    "run",
    ds["cpu_time"].values / paper["cpu_time"],
    {"units": "1", "long_name": "CPU time / paper's method (sign+RK45 rtol 1e-3), same run"},
)
ds.attrs.update(
    title=f"Work-precision of integration methods, scene {scene}",
    paper_method_cpu_time=paper["cpu_time"],
    paper_method_rhs_evaluations=paper["rhs_evaluations"],
    reference_period=ref_cycle["period"],
    reference_amplitude=ref_cycle["amplitude"],
    t_end=cfg["t_end"],
)
write(
    ds,
    snakemake.output[0],
    scene={"name": scene, **model.params.as_dict(), "variant": model.variant},  # noqa: F821
    method={
        "reference": "exact",
        "paper_method": cfg["paper_method"],
        "budget": cfg["budget"],
        "timing": cfg["timing"],
    },
)
