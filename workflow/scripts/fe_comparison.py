"""Continuum strip vs beam on every paper scene -> results/fe/continuum/*.nc, model_comparison.csv/.nc."""

import csv

from stickslip.fe.params import FrictionTable
from stickslip.fe.quantities import INTERPRETATION
from stickslip.io.netcdf import read_dataset, write_dataset
from stickslip.io.progress import log_to_file
from stickslip.schema.fe import FeJob
from stickslip.studies.fe_comparison import (
    comparison_dataset,
    comparison_rows,
    noise_floors,
    window_rows,
)
from stickslip.studies.fe_config import comparison_mapping, halved_step
from stickslip.studies.fe_continuum import continuum_dataset
from stickslip.studies.fe_scene import run_scene

log_to_file(snakemake.log[0], capture_output=True)  # noqa: F821
job = FeJob.model_validate(snakemake.params.config)  # noqa: F821  (every scene resolved, the comparison)
cmp = job.comparison
nx, ny = cmp.mesh
friction = FrictionTable.from_csv(snakemake.input.friction)  # noqa: F821
cont, beam, floors, half = {}, {}, {}, {}
for name, path in zip(snakemake.params.scenes, snakemake.output.continuum, strict=True):  # noqa: F821
    mapping = comparison_mapping(job, name)
    cont[name] = continuum_dataset(mapping, friction, nx=nx, ny=ny, name=name)
    write_dataset(cont[name], path, scene=mapping, interpretation=INTERPRETATION, method={"mesh": [nx, ny]})
    beam[name] = run_scene(mapping, friction)[1]
    half[name] = run_scene(halved_step(mapping), friction)[1]
    floors[name] = noise_floors(beam[name], half[name])
    print(f"{name}: continuum cpu {float(cont[name]['cpu_time']):.1f} s, beam {beam[name]['cpu_time']:.2f} s")
rows = comparison_rows(cont, beam, cmp.notes, floors, half)
# over a claim's window: the continuum runs of rule fe_continuum_window against the default reading's beam
scenes = snakemake.params.window_scenes  # noqa: F821
window = {s: read_dataset(p) for s, p in zip(scenes, snakemake.input.window, strict=True)}  # noqa: F821
beam_window = {s: read_dataset(p) for s, p in zip(scenes, snakemake.input.beam, strict=True)}  # noqa: F821
rows += window_rows(window, beam_window, cmp.notes)
with open(snakemake.output.table, "w", newline="") as f:  # noqa: F821
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
write_dataset(
    comparison_dataset(rows, cont, beam),
    snakemake.output.dataset,  # noqa: F821
    scene=cmp.model_dump(exclude_none=True),
    interpretation=INTERPRETATION,
    method={"kind": "model comparison", "t_end": cmp.t_end},
)
