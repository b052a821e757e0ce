"""Thin wiring: the report's captions (which paper figure each image shows; claim statuses)."""

import yaml

from stickslip import catalogue as paths
from stickslip.claims.table import read_table
from stickslip.io.text_files import write_text_atomic
from stickslip.presentation.report import caption_template, caption_text, claims_for
from stickslip.schema import Figure

params = snakemake.params  # noqa: F821
rows = read_table(snakemake.input.table)  # noqa: F821
notes = yaml.safe_load(open(snakemake.input.figures))  # noqa: F821
captions = {}
for name, fig in ((name, Figure.model_validate(spec)) for name, spec in params.figures.items()):
    figs = set(fig.paper_figures)
    for reading in fig.readings:
        captions[paths.figure(name, reading)] = caption_text(
            f"{fig.title or name} — reading {reading}",
            figs,
            claims_for(rows, figs, reading),
            note=f"Methods overlaid: {', '.join(fig.methods)}. A failed solver run is labelled as such, "
            "never drawn as a result.",
        )
# each beam-on-disc image: its figures from config fe.paper_figures (catalogue), its note from figures.yaml
for path, image in params.fe_images.items():
    figs = set(image["figures"])
    note = notes["fe"].get(image["name"], {}).get("note", "")
    captions[path] = caption_text(
        f"Beam on rotating disc, {image['name']}", figs, claims_for(rows, figs), note=note
    )
# each notebook: the paper figures of what it reads (report.smk notebook_paper_figures)
for name, figures in params.notebooks.items():
    figs = set(figures)
    captions[paths.notebook(name)] = caption_text(
        f"Notebook {name}: figures next to the reported numbers", figs, claims_for(rows, figs)
    )
if params.methods_scenes:
    scenes = params.methods_scenes
    wp, fm = notes["methods"]["work_precision"], notes["methods"]["failure_map"]
    captions[paths.figure("methods", f"{scenes[0]}_work_precision")] = caption_text(
        f"Integration methods: work-precision charts ({', '.join(scenes)}) and failure map",
        set(),
        [],
        note=f"{wp['note']} {fm['note']}",
    )
    captions[paths.notebook("methods_work_precision")] = caption_text(
        "Notebook methods_work_precision: the integration-methods study", set(), [], note=wp["note"]
    )
captions[paths.claims_table()] = caption_text(
    "The claims table: every reported number versus what this run measured",
    set(),
    rows,
    note="Status per claim and reading, with the margin to the claim's threshold and the spread over the "
    "perturbation ensemble; a status that differs from its pin is shown with the pinned one.",
)
write_text_atomic(snakemake.output[0], caption_template(captions))  # noqa: F821
