"""The configuration as typed models (pydantic v2): one model per config section, one module per config file.

Every mapping forbids unknown keys, every number must be finite (no NaN or inf), bounds are physical
(masses, stiffnesses, durations > 0), and an error names the full key (``onedof.scenes.fig02.params.mass``).
Modules: ``base`` (the mapping bases, number types, reference helpers and the params helpers of the rules),
``onedof`` (config.yaml's sections), ``dense_map``, ``methods``, ``fe``, ``inverse``, ``validation``, and
``config`` (``PipelineConfig``: the whole config, its cost guard and JSON schema). The package sits below
the studies (``tests/pipeline/test_layers.py``), so a study, the inverse study and the validations take the
typed section they read, not a mapping.

Every name is taken from the package (``from stickslip.schema import OnedofJob``) and its module is loaded
on first use: a job that types its own section's params loads that section's module, not the whole config's
(~35 ms of the ~86 ms of every model). Loaded by name, as the solvers' registry: the pipeline's code hash
counts every module of the package for such a name (``stickslip.pipeline.code_deps``).
"""

from importlib import import_module

#: Where a name is looked up, in order (a name one module takes from an earlier one is the earlier one's).
MODULES = ("base", "onedof", "dense_map", "methods", "fe", "inverse", "validation", "config")


def __getattr__(name: str):
    for module in MODULES:
        found = getattr(import_module(f".{module}", __name__), name, MODULES)
        if found is not MODULES:
            return found
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
