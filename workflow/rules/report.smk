# Captions for `snakemake --report results/report.html`: every figure with the paper figure it shows (a label,
# never a verdict) and the statuses of its claims (read from the deviations table of the same run).


rule report_captions:
    input:
        table=paths.claims_table(),
        figures="workflow/report/figures.yaml",
    output:
        **outputs("report_captions"),
    log:
        paths.log("report_captions", "all"),
    benchmark:
        paths.benchmark("report_captions", "all")
    conda:
        CONDA_ENV
    params:
        # everything the captions read: rerun when a figure, FE image, methods scene or notebook changes
        figures=as_params(CFG.onedof.figures),
        # each beam-on-disc image's paper figures, from the catalogue (config fe.paper_figures)
        fe_images={
            path: {"name": entry.name("name"), "figures": list(entry.figures)}
            for path, entry in CATALOGUE.items()
            if entry.kind == "figure" and entry.name("group") == "fe" and entry.figures
        },
        methods_scenes=list(CFG.methods_study.scenes),
        notebooks={name: notebook_paper_figures(name) for name in CFG.notebooks},
    script:
        "../scripts/report_captions.py"


ALL_TARGETS.append(REPORT_CAPTIONS)
