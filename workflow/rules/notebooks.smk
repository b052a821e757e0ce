# Rendered comparison notebooks (jupytext percent files in notebooks/, executed here, HTML in results/).


import json
import shlex


def notebook_params(name):
    """What the notebook is told: its figures' specs (scene, readings, methods) and the claims readings."""
    spec = config["notebooks"][name]
    return {
        "figures": {fig: ONEDOF["figures"][fig] for fig in spec.get("figures", [])},
        "claims_readings": config["claims"]["readings"],
    }


def notebook_inputs(name):
    spec = config["notebooks"][name]
    files = list(spec.get("inputs", []))
    for fig in spec.get("figures", []):
        files += figure_datasets(fig)
        files += [f"results/figures/{fig}/{r}.png" for r in ONEDOF["figures"][fig]["readings"]]
    return files + ["results/claims/deviations.csv"]


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
    params:
        python=sys.executable,
        nb_params=lambda wc: shlex.quote(json.dumps(notebook_params(wc.name))),
    shell:
        "{params.python} {workflow.basedir}/workflow/scripts/render_notebook.py {input.notebook} {output} "
        "{params.nb_params} > {log} 2>&1"


ALL_TARGETS.extend(f"results/notebooks/{name}.html" for name in config["notebooks"])
