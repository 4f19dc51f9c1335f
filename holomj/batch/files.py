"""Durable appends for batch runs (they survive ``kill -9``); whole files are written with
:func:`holomj.atomic.write_file`."""

from __future__ import annotations

import os
from pathlib import Path


def append_line_synced(path: Path, line: str) -> None:
    """Append one line to ``path`` and fsync it, so a crash right after keeps the line."""
    with open(path, "a", encoding="utf-8") as handle:
        handle.write(line.rstrip("\n") + "\n")
        handle.flush()
        os.fsync(handle.fileno())
