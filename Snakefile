# Stick-slip replication pipeline: every figure of the paper is a rule.
# Configuration: every config/*.yaml (one file per concern); `--configfile config/test/*.yaml` shrinks it.
import os
import sys
from pathlib import Path

from snakemake.utils import update_config

sys.path.insert(0, str(Path(workflow.basedir) / "src"))  # the package, also when not pip-installed
# ... and every job imports this project's own package first, whatever venv runs it: in a copied or moved
# project the venv's editable install still points at the original's src/ (the Makefile rebuilds such a
# venv; a Snakemake started from another project's venv is covered here).
# (set, not required: hence no `envvars:` directive)
os.environ.update(
    PYTHONPATH=os.pathsep.join(
        [str(Path(workflow.basedir, "src").resolve())] + [p for p in [os.environ.get("PYTHONPATH")] if p]
    )
)

from stickslip.pipeline.config import load_config  # noqa: E402

# The config files are read by the project's loader, not Snakemake's `configfile:`: data only (Snakemake's
# would run a file marked `__use_yte__` as a template), duplicate keys and syntax errors named with file and
# line. `--configfile` overrides are read again the same way; `--config key=value` applies last.
#: The config files, in the order they are merged (a config error names the file and line of its key).
CONFIG_FILES = [str(p) for p in sorted(Path(workflow.basedir, "config").glob("*.yaml"))] + [
    str(p) for p in workflow.overwrite_configfiles or []
]
update_config(config, load_config(CONFIG_FILES))
update_config(config, dict(workflow.config_settings.config or {}))

from stickslip.pipeline import results_owner  # noqa: E402

#: The --configfile overlays of this build: a results folder holds the build of one configuration only.
CONFIG_OVERLAYS = results_owner.overlays(CONFIG_FILES, workflow.basedir)


include: "workflow/rules/common.smk"


for _smk in sorted(Path(workflow.basedir, "workflow", "rules").glob("*.smk")):
    if _smk.name != "common.smk":

        include: str(_smk)


# Every rule's job re-runs when a package module it imports changes (stickslip.pipeline.code_deps): one more
# parameter per rule, the hash of those modules, set after every rule is defined.
for _rule in workflow.rules:
    _rule.set_params(code=rule_code_hash(_rule))

check_inputs_producible(list(workflow.rules))
# every dataset, not only the final products: a deleted intermediate dataset is rebuilt by the default build
# (a list of its own: the page and the benchmark summary read ALL_TARGETS, the final products)
EVERY_DATASET = [p for p in catalogue_datasets(workflow.rules) if p not in set(ALL_TARGETS)]


rule all:
    default_target: True
    input:
        ALL_TARGETS,
        EVERY_DATASET,


# Only a build that runs jobs (not a dry run) claims the results folder, after checking it is not another
# configuration's (stickslip.pipeline.results_owner).
onstart:
    results_owner.claim(paths.RESULTS, CONFIG_OVERLAYS)
