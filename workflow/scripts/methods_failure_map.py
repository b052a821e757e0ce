"""Snakemake script: failure map over (parameter value, method setting)."""

import os
import sys

import numpy as np
import xarray as xr

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from methods_common import expand_methods, records_dataset, run_scene, scene_model, write  # noqa: E402

cfg = snakemake.params.study  # noqa: F821
fm = cfg["failure_map"]
methods = expand_methods(fm["methods"])
rows = []
for value in fm["values"]:
    model = scene_model(cfg, fm["scene"], **{fm["parameter"]: value})
    records, *_ = run_scene(cfg, model, fm["t_end"], methods, paper=False)
    rows.append(records_dataset(records))
ds = xr.concat(rows, dim="parameter")
ds = ds.assign_coords(
    parameter=(
        "parameter",
        np.array(fm["values"], dtype=float),
        {
            "long_name": f"swept parameter {fm['parameter']}",
            "units": "s mm-1" if fm["parameter"] == "sigma" else "1",
        },
    ),
    run=("run", np.arange(len(methods))),
)
ds["label"] = ("run", np.array([m[2] for m in methods], dtype=object), {"long_name": "method and settings"})
ds.attrs.update(
    title="Failure map of integration methods", swept_parameter=fm["parameter"], t_end=fm["t_end"]
)
write(
    ds,
    snakemake.output[0],
    scene={"name": fm["scene"], "sweep": fm["parameter"], "values": fm["values"]},  # noqa: F821
    method={"reference": "exact", "methods": fm["methods"], "budget": cfg["budget"]},
)
