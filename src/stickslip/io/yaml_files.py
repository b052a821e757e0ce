"""Reading the project's YAML files: data only, every mistake named with its file and line.

Snakemake's own config loader evaluates a file that sets ``__use_yte__: true`` as a template (Python
expressions run at load time) and, like PyYAML, keeps the last of two equal keys without a word. The
project's config and claims files are read here instead: a safe loader (no tags, no code), duplicate keys
rejected, the template key rejected, aliases that expand a file beyond ``MAX_EXPANDED_NODES`` rejected (an
alias copies a node, so a few lines of aliases can expand to gigabytes: a "billion laughs"), and a syntax
error reported as
``file:line:column: problem``. ``key_location`` finds the file and line that set a config key, for
errors found after loading.
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


#: Most nodes a file may hold once its aliases are expanded. The largest file of the project holds a few
#: thousand; a "billion laughs" of ten lines holds 10^9. Checked on the composed graph (an alias is the
#: same node object there, so nothing is expanded), in time linear in the file.
MAX_EXPANDED_NODES = 1_000_000


def _expanded_size(root, sizes: dict[int, int] | None = None) -> int:
    """Nodes under ``root`` once every alias is expanded (``sizes``, if given, gets every node's)."""
    sizes = {} if sizes is None else sizes
    stack = [(root, False)]
    while stack:
        node, done = stack.pop()
        if id(node) in sizes:
            continue
        children = (
            [c for pair in node.value for c in pair]
            if isinstance(node, yaml.MappingNode)
            else list(node.value)
            if isinstance(node, yaml.SequenceNode)
            else []
        )
        if done or not children:
            sizes[id(node)] = 1 + sum(sizes[id(c)] for c in children)
        else:
            stack.append((node, True))
            stack += [(c, False) for c in children if id(c) not in sizes]
    return sizes[id(root)]


def _refuse_alias_bombs(path: Path, text: str) -> None:
    """A file whose aliases expand to more than ``MAX_EXPANDED_NODES`` nodes is an error naming the place
    of its first alias, before anything is expanded."""
    if "*" not in text:
        return
    root = yaml.compose(text, Loader=_BASE)
    if root is None:
        return
    sizes: dict[int, int] = {}
    size = _expanded_size(root, sizes)
    if size > MAX_EXPANDED_NODES:
        key, node = _largest_entry(root, sizes)
        raise YamlFileError(
            f"{_where(path, node.start_mark)}: {key or 'the document'}: YAML aliases expand it to "
            f"{sizes[id(node)]:.3g} nodes (the file to {size:.3g}), more than the limit "
            f"{MAX_EXPANDED_NODES:.0e}: config files are plain data"
        )


def _largest_entry(root, sizes: dict[int, int]) -> tuple[str, object]:
    """The dotted key of the deepest mapping entry that alone expands beyond the limit, and its node (the
    place to name: the entry that blows up, not the first alias of the file)."""
    key, node = "", root
    while isinstance(node, yaml.MappingNode):
        big = [(k, v) for k, v in node.value if sizes[id(v)] > MAX_EXPANDED_NODES]
        if not big:
            break
        k, node = big[0]
        key = f"{key}.{k.value}" if key else str(k.value)
    return key, node


def _key_parts(key: str) -> list:
    """``a.b[2].c`` -> ['a', 'b', 2, 'c']."""
    parts: list = []
    for piece in key.split("."):
        name, *indices = piece.split("[")
        if name:
            parts.append(name)
        parts += [int(i.rstrip("]")) for i in indices if i.rstrip("]").isdigit()]
    return parts


def _depth_and_line(node, parts: list) -> tuple[int, int]:
    """How many leading parts of a key the node tree has, and the line of the deepest one (1-based)."""
    depth, line = 0, node.start_mark.line + 1
    for part in parts:
        if isinstance(node, yaml.MappingNode):
            found = next(((k, v) for k, v in node.value if k.value == str(part)), None)
            if found is None:
                break
            line, node = found[0].start_mark.line + 1, found[1]
        elif isinstance(node, yaml.SequenceNode) and isinstance(part, int) and part < len(node.value):
            node = node.value[part]
            line = node.start_mark.line + 1
        else:
            break
        depth += 1
    return depth, line


def key_location(key: str, paths) -> str | None:
    """``file:line`` of the config file that sets ``key`` (dotted, ``[i]`` for list items), or of its
    deepest parent that one of them sets; of two files that set it equally deep the later (the override).
    None when no file has even its first part. Only called for an error: each file is parsed again."""
    parts = _key_parts(key)
    best = (0, None)
    for path in paths:
        try:
            text = Path(path).read_text()
            _refuse_alias_bombs(Path(path), text)
            root = yaml.compose(text, Loader=_BASE)
        except (OSError, YamlFileError, yaml.YAMLError):
            continue
        if root is None:
            continue
        depth, line = _depth_and_line(root, parts)
        if depth and depth >= best[0]:
            best = (depth, f"{path}:{line}")
    return best[1]


def load_yaml(path: str | Path):
    """The data in one YAML file (None for an empty file)."""
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise YamlFileError(f"{path}: cannot read ({exc.strerror or exc})") from None
    try:
        _refuse_alias_bombs(path, text)
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
