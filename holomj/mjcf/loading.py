"""Loading MJCF files from disk with errors that name the file."""

from __future__ import annotations

from pathlib import Path

import mujoco

from holomj.errors import FormatError


def load_model_file(path: Path) -> mujoco.MjModel:
    """``mujoco.MjModel.from_xml_path`` with a one-line FormatError naming ``path``."""
    if not Path(path).is_file():
        raise FormatError("file not found", where=str(path))
    try:
        return mujoco.MjModel.from_xml_path(str(path))
    except ValueError as err:
        raise FormatError(
            f"MuJoCo cannot load it: {' '.join(str(err).split())}", where=str(path)
        ) from None
