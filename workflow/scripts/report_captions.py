"""Thin wiring: the report's captions (which paper figure each image shows; claim statuses)."""

import yaml

from stickslip import catalogue as paths
from stickslip.claims.table import read_table
from stickslip.presentation.report import caption_text, claims_for, write_captions

rows = read_table(snakemake.input.table)  # noqa: F821
spec = yaml.safe_load(open(snakemake.input.figures))  # noqa: F821
config = snakemake.params.config  # noqa: F821
captions = {}
for fig, fspec in config["onedof"]["figures"].items():
    figs = set(fspec["paper_figures"])  # config onedof.figures.<fig>.paper_figures
    for reading in fspec["readings"]:
        captions[paths.figure(fig, reading)] = caption_text(
            f"{fspec.get('title', fig)} — reading {reading}",
            figs,
            claims_for(rows, figs, reading),
            note=f"Methods overlaid: {', '.join(fspec['methods'])}. A failed solver run is labelled as such, "
            "never drawn as a result.",
        )
# each beam-on-disc image: its figures from config fe.paper_figures (catalogue), its note from figures.yaml
for path, image in config["fe_images"].items():
    note = spec["fe"].get(image["name"], {}).get("note", "")
    title = f"Beam on rotating disc, {image['name']}"
    figs = set(image["figures"])
    captions[path] = caption_text(title, figs, claims_for(rows, figs), note=note)
if config["methods_study"]["scenes"]:
    scenes = list(config["methods_study"]["scenes"])
    wp, fm = spec["methods"]["work_precision"], spec["methods"]["failure_map"]
    captions[paths.figure("methods", f"{scenes[0]}_work_precision")] = caption_text(
        f"Integration methods: work-precision charts ({', '.join(scenes)}) and failure map",
        set(),
        [],
        note=f"{wp['note']} {fm['note']}",
    )
for name, nspec in config.get("notebooks", {}).items():
    figs = set().union(
        *[set(config["onedof"]["figures"][f]["paper_figures"]) for f in nspec.get("figures", [])]
    )
    captions[paths.notebook(name)] = caption_text(
        f"Notebook {name}: figures next to the reported numbers", figs, claims_for(rows, figs)
    )
if config["fe"]["scenes"]:
    figs = set(range(17, 37))
    captions[paths.notebook("section_09_12_beam_on_disc")] = caption_text(
        "Notebook section_09_12_beam_on_disc: the beam-on-disc scenes next to the reported numbers",
        figs,
        claims_for(rows, figs),
    )
if config["methods_study"]["scenes"]:
    captions[paths.notebook("methods_work_precision")] = caption_text(
        "Notebook methods_work_precision: the integration-methods study",
        set(),
        [],
        note=spec["methods"]["work_precision"]["note"],
    )
captions[paths.claims_table()] = caption_text(
    "The claims table: every reported number versus what this run measured",
    set(),
    rows,
    note="Status per claim and reading, with the margin to the claim's threshold and the spread over the "
    "perturbation ensemble; a status that differs from its pin is shown with the pinned one.",
)
write_captions(captions, snakemake.output[0])  # noqa: F821
