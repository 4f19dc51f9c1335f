"""Atomic folder writes: build beside the target, then rename into place.

Used by every writer of folders (exported scenes, asset libraries), so a crash or a rejected
input never leaves a half-written folder and an existing one is only replaced once the new one
is complete.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Callable
from pathlib import Path


def replace_folder(target: Path, fill: Callable[[Path], None]) -> None:
    """Create ``target`` with ``fill(tmp)`` run on an empty temporary folder beside it.

    An existing ``target`` is moved aside, the new folder renamed into place, and the old one
    deleted; if the rename fails, the old folder is put back. ``fill``'s exceptions propagate
    and leave ``target`` as it was.
    """
    target = Path(target).absolute()
    parent = target.parent
    parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.new-", dir=parent))
    try:
        fill(tmp)
        os.chmod(tmp, 0o755)
        if not target.exists():
            os.replace(tmp, target)
            return
        old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=parent))
        os.rmdir(old)
        os.replace(target, old)
        try:
            os.replace(tmp, target)
        except BaseException:
            os.replace(old, target)
            raise
        shutil.rmtree(old, ignore_errors=True)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)
