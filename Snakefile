# Stick-slip replication pipeline: every figure of the paper is a rule.
# Configuration: every config/*.yaml (one file per concern); `--configfile config/test/*.yaml` shrinks it.
from pathlib import Path

for _cfg in sorted(Path(workflow.basedir, "config").glob("*.yaml")):

    configfile: str(_cfg)


include: "workflow/rules/common.smk"


for _smk in sorted(Path(workflow.basedir, "workflow", "rules").glob("*.smk")):
    if _smk.name != "common.smk":

        include: str(_smk)


rule all:
    default_target: True
    input:
        ALL_TARGETS,
