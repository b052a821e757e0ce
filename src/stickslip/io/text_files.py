"""Text results (decks, tables) written atomically: a hidden temporary file in the target folder, then
renamed, so an interrupted job never leaves a readable partial file under the target name."""

from __future__ import annotations

import csv
import io
import os
import tempfile
from pathlib import Path


def publish(tmp: str | os.PathLike, path: str | os.PathLike) -> None:
    """Give a finished temporary file the permissions of a normally created one, then rename it into place.

    mkstemp creates files readable by their owner only: every atomic writer of the project (datasets, decks,
    tables, pages) publishes through here, so every result has the mode the umask gives a new file.
    """
    mask = os.umask(0)
    os.umask(mask)
    os.chmod(tmp, 0o666 & ~mask)
    os.replace(tmp, path)


def write_text_atomic(path: str | os.PathLike, text: str) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
        publish(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def write_csv_atomic(
    path: str | os.PathLike, rows: list[dict], *, fields: list[str] | None = None, lineterminator: str = "\n"
) -> Path:
    """Rows (dicts with the same keys) as CSV with a header line of ``fields`` (default: the first row's
    keys; with ``fields`` a table may have no rows)."""
    if not rows and fields is None:
        raise ValueError(f"{path}: no rows to write")
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=fields or list(rows[0]), lineterminator=lineterminator)
    w.writeheader()
    w.writerows(rows)
    return write_text_atomic(path, buf.getvalue())
