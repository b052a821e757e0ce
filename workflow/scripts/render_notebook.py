"""Execute a jupytext percent-format notebook and render it to HTML.

usage: python workflow/scripts/render_notebook.py notebooks/NAME.py results/notebooks/NAME.html [PARAMS.json]

PARAMS (optional JSON text) is injected as ``PARAMS = {...}`` in a cell before the notebook's first code cell,
so the pipeline can tell a notebook which scenes/readings it built (papermill-style, without the dependency).

Runs with the current directory (the repo root under Snakemake) as the kernel's working directory, writes
the HTML atomically, and exits non-zero if any cell fails.
"""

import json
import os
import sys
import tempfile
from pathlib import Path

import jupytext
import nbformat
from nbclient import NotebookClient
from nbconvert import HTMLExporter

from stickslip.io.netcdf import publish


def render(source: Path, target: Path, params: dict | None = None, timeout: int = 600) -> None:
    nb = jupytext.read(source)
    if params is not None:
        first_code = next(i for i, c in enumerate(nb.cells) if c.cell_type == "code")
        cell = nbformat.v4.new_code_cell(
            f"# Parameters injected by the pipeline\nimport json\nPARAMS = json.loads({json.dumps(params)!r})"
        )
        nb.cells.insert(first_code, cell)
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    NotebookClient(
        nb, timeout=timeout, kernel_name="python3", resources={"metadata": {"path": os.getcwd()}}
    ).execute()
    body, _ = HTMLExporter(template_name="classic").from_notebook_node(nb)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", dir=target.parent)
    with os.fdopen(fd, "w") as fh:
        fh.write(body)
    publish(tmp, target)
    ipynb = target.with_suffix(".ipynb")
    nbformat.write(nb, ipynb)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    render(Path(sys.argv[1]), Path(sys.argv[2]), json.loads(sys.argv[3]) if len(sys.argv) == 4 else None)
