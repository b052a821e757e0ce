# Rendered comparison notebooks (jupytext percent files in notebooks/, executed here, HTML in results/).


rule render_notebook:
    input:
        notebook="notebooks/{name}.py",
        data=lambda wc: notebook_inputs(wc.name),
    output:
        report(
            "results/notebooks/{name}.html",
            caption=REPORT_CAPTION_FILE,
            category="Notebooks",
            labels={"notebook": "{name}"},
        ),
    log:
        "results/logs/render_notebook/{name}.log",
    benchmark:
        "results/benchmarks/render_notebook/{name}.tsv"
    wildcard_constraints:
        name="|".join(config["notebooks"]),
    conda:
        CONDA_ENV
    params:
        python=sys.executable,
        script=str(Path(workflow.basedir) / "workflow" / "scripts" / "render_notebook.py"),
        nb_params=lambda wc: shlex.quote(json.dumps(notebook_params(wc.name))),
    shell:
        "{params.python} {params.script} {input.notebook} {output} " "{params.nb_params} > {log} 2>&1"


ALL_TARGETS.extend(f"results/notebooks/{name}.html" for name in config["notebooks"])
