"""How a typed-model error reads: one line per problem, the dotted key first."""

from __future__ import annotations


def typed_errors(exc) -> str:
    """A pydantic ValidationError as one line per problem: ``dotted.key: message (got value)``."""
    lines = []
    for err in exc.errors():
        key = "".join(f"[{part}]" if isinstance(part, int) else f".{part}" for part in err["loc"]).lstrip(".")
        if err["type"] == "value_error":  # a validator's own message (cross-references name their key)
            text = str(err["ctx"]["error"])
            lines.append(text if not key or text.startswith(key) else f"{key}: {text}")
            continue
        got = "" if err["type"] == "missing" else f" (got {err['input']!r})"
        lines.append(f"{key}: {err['msg']}{got}")
    return "\n".join(lines)
