"""Reading the project's YAML files: data only, every mistake named with its file and line.

Snakemake's own config loader evaluates a file that sets ``__use_yte__: true`` as a template (Python
expressions run at load time) and, like PyYAML, keeps the last of two equal keys without a word. The
project's config and claims files are read here instead: a safe loader (no tags, no code), duplicate keys
rejected, the template key rejected, and a syntax error reported as ``file:line:column: problem``.
"""

from __future__ import annotations

from pathlib import Path

import yaml

#: The key with which Snakemake would run a config file as a YTE template.
TEMPLATE_KEY = "__use_yte__"

_BASE = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml where present: ~7x faster, same objects


class YamlFileError(ValueError):
    """A YAML file cannot be read as data; the message starts with ``file:line:column``."""


class _StrictLoader(_BASE):  # type: ignore[misc, valid-type]
    """Safe loading that refuses a mapping with two equal keys."""


def _construct_mapping(loader, node, deep=False):
    seen = {}
    for key_node, _ in node.value:
        # a scalar key compared by its tag and text: constructing every key twice doubled the load time
        key = (key_node.tag, key_node.value) if isinstance(key_node, yaml.ScalarNode) else id(key_node)
        if key in seen:
            mark = key_node.start_mark
            raise yaml.constructor.ConstructorError(
                None,
                None,
                f"duplicate key {key_node.value!r} (first at line {seen[key] + 1}): YAML keeps only the last",
                mark,
            )
        seen[key] = key_node.start_mark.line
    return yaml.SafeLoader.construct_mapping(loader, node, deep=deep)


_StrictLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


def _where(path: Path, mark) -> str:
    return f"{path}:{mark.line + 1}:{mark.column + 1}" if mark is not None else str(path)


def load_yaml(path: str | Path):
    """The data in one YAML file (None for an empty file)."""
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise YamlFileError(f"{path}: cannot read ({exc.strerror or exc})") from None
    try:
        data = yaml.load(text, Loader=_StrictLoader)
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        problem = " ".join(str(p) for p in (exc.context, exc.problem) if p)
        raise YamlFileError(f"{_where(path, mark)}: {problem}") from None
    except yaml.YAMLError as exc:
        raise YamlFileError(f"{path}: {exc}") from None
    if isinstance(data, dict) and TEMPLATE_KEY in data:
        raise YamlFileError(
            f"{path}: {TEMPLATE_KEY}: config files are data, never templates (Snakemake would run the Python "
            "expressions in this file while loading it)"
        )
    return data
