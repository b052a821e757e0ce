"""The methods study's config entries: one entry with a ``sweep`` of settings is many methods."""

from __future__ import annotations

import itertools


def expand_methods(entries) -> list[tuple[str, dict, str]]:
    """Config method entries -> list of (solver name, settings dict, label), one per swept combination."""
    out = []
    for entry in entries:
        fixed = dict(entry.get("settings", {}))
        sweep = entry.get("sweep", {})
        keys = list(sweep)
        for combo in itertools.product(*(sweep[k] for k in keys)) if keys else [()]:
            settings = dict(fixed, **dict(zip(keys, combo)))
            if "atol_per_rtol" in entry and "rtol" in settings:
                settings["atol"] = settings["rtol"] * entry["atol_per_rtol"]
            label = entry["solver"] + (
                "[" + ",".join(f"{k}={v}" for k, v in settings.items()) + "]" if settings else ""
            )
            out.append((entry["solver"], settings, label))
    return out
