"""How a typed-model error reads: one line per problem, the dotted key first."""

from __future__ import annotations

import re

#: Longest rendering of an offending value in a message (a huge value would flood the log).
MAX_VALUE_CHARS = 120


def _short(value) -> str:
    text = repr(value)
    return text if len(text) <= MAX_VALUE_CHARS else f"{text[:MAX_VALUE_CHARS]}... ({len(text)} characters)"


def typed_errors(exc) -> str:
    """A pydantic ValidationError as one line per problem: ``dotted.key: message (got value)``."""
    lines = []
    for err in exc.errors():
        key = "".join(f"[{part}]" if isinstance(part, int) else f".{part}" for part in err["loc"]).lstrip(".")
        if err["type"] == "value_error":  # a validator's own message (cross-references name their key)
            text = str(err["ctx"]["error"])
            if key and not text.startswith(key) and re.match(r"[A-Za-z_][\w\[\]]*(\.[\w\[\]]+)*: ", text):
                lines.append(f"{key}.{text}")  # the validator named a sub-key: `windows[0]: ...`
            else:
                lines.append(text if not key or text.startswith(key) else f"{key}: {text}")
            continue
        got = "" if err["type"] == "missing" else f" (got {_short(err['input'])})"
        lines.append(f"{key}: {err['msg']}{got}")
    return "\n".join(lines)
