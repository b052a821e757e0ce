"""Execute a jupytext percent-format notebook and render it to HTML for a reader of the paper.

usage: python workflow/scripts/render_notebook.py notebooks/NAME.py results/notebooks/NAME.html [PARAMS.json]

PARAMS (optional JSON text) is set as ``PARAMS`` in a cell before the notebook's first code cell; the HTML
shows neither that cell nor any code (each cell's code is in a collapsed block, the source linked at the
top; see presentation.notebook.render). The executed notebook, parameters included, is written next to the
HTML (.ipynb). Runs in the current directory (the repo root under Snakemake); exits non-zero if a cell fails.
"""

import json
import sys
from pathlib import Path

from stickslip.presentation.notebook import render

if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    render(Path(sys.argv[1]), Path(sys.argv[2]), json.loads(sys.argv[3]) if len(sys.argv) == 4 else None)
