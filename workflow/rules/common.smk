# Shared definitions for every rules file: config validation, target list, helpers.
import sys
from pathlib import Path

from snakemake.utils import validate

sys.path.insert(0, str(Path(workflow.basedir) / "src"))  # the package, also when not pip-installed

validate(config, "../schemas/config.schema.yaml")

#: Final outputs; every rules file appends its own.
ALL_TARGETS = []

ONEDOF = config["onedof"]

#: One caption template for every figure of `snakemake --report` (written by rule report_captions). An
#: absolute path under the working directory, since report() resolves captions against the rules folder.
REPORT_CAPTIONS = "results/report/captions.rst"
REPORT_CAPTION_FILE = str(Path(REPORT_CAPTIONS).resolve())


def onedof_dataset(scene, reading, method):
    return f"results/onedof/{scene}/{reading}/{method}.nc"


def figure_datasets(figure):
    fig = ONEDOF["figures"][figure]
    return [onedof_dataset(fig["scene"], r, m) for r in fig["readings"] for m in fig["methods"]]
