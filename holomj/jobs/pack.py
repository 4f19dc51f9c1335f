"""The pack job (``holomj pack OUT [--format mjb|zip|all]``): a scene folder as one file.

- ``mjb``: MuJoCo's binary model (default ``OUT/export/scene.mjb``), compiled once from
  ``scene.xml``; ``mujoco.MjModel.from_binary_path`` loads it without parsing XML or meshes.
- ``zip``: the folder's ``scene.xml`` with its meshes, textures and JSON records (default
  ``OUT/export/scene.zip``); extract it, or load it from its bytes
  (:func:`holomj.formats.package.load_package`).

Each file is checked before it replaces the previous one: it is loaded back and must have the
scene's bodies, geoms, joints and initial pose. Writes are atomic.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from holomj.atomic import write_file
from holomj.errors import ExportError, InputError
from holomj.file_names import SCENE_XML
from holomj.formats.package import folder_zip, load_package, model_mjb, zip_model
from holomj.jobs.export import EXPORT_DIR
from holomj.jobs.folder import require_scene_folder

PACK_FORMATS = ("mjb", "zip")


@dataclass
class PackResult:
    """What :func:`pack_folder` wrote: one path and size per format, and timings."""

    folder: str
    files: dict[str, str] = field(default_factory=dict)
    bytes: dict[str, int] = field(default_factory=dict)
    timings_s: dict[str, float] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def pack_formats(fmt: str) -> tuple[str, ...]:
    """The formats ``fmt`` names (``all``: both); an unknown one is an InputError."""
    value = str(fmt).strip().lower()
    if value == "all":
        return PACK_FORMATS
    if value not in PACK_FORMATS:
        raise InputError(f"unknown package format {fmt!r}", where="--format", fix="mjb, zip or all")
    return (value,)


def pack_folder(out: Path, fmt: str = "all", target_dir: Path | None = None) -> PackResult:
    """Write the scene folder ``out`` as ``scene.mjb`` and/or ``scene.zip`` into ``target_dir``
    (default ``OUT/export``) and return what was written."""
    formats = pack_formats(fmt)
    folder = require_scene_folder(Path(out), "holomj compile' or 'holomj generate")
    directory = Path(target_dir) if target_dir is not None else folder / EXPORT_DIR
    if directory.exists() and not directory.is_dir():
        raise InputError("is a file, not a folder", where=str(directory), fix="name a folder")
    clock = time.perf_counter()
    model = load_package(folder / SCENE_XML)
    result = PackResult(str(folder), timings_s={"load_xml": time.perf_counter() - clock})
    directory.mkdir(parents=True, exist_ok=True)
    for name in formats:
        clock = time.perf_counter()
        data = model_mjb(model) if name == "mjb" else folder_zip(folder)
        _check_same(model, _reload(name, data), name)
        target = directory / f"scene.{name}"
        try:
            write_file(target, data)
        except OSError as err:
            raise ExportError(f"writing failed: {err.strerror or err}", where=str(target)) from None
        result.files[name] = str(target)
        result.bytes[name] = len(data)
        result.timings_s[name] = time.perf_counter() - clock
    result.timings_s = {key: round(value, 4) for key, value in result.timings_s.items()}
    return result


def _reload(fmt: str, data: bytes) -> mujoco.MjModel:
    if fmt == "zip":
        return zip_model(data)
    return mujoco.MjModel.from_binary_path("scene.mjb", {"scene.mjb": data})


def model_differences(expected: mujoco.MjModel, actual: mujoco.MjModel) -> list[str]:
    """What differs between two models of one scene: counts, initial pose, geom sizes."""
    problems = [
        f"{name}: {getattr(expected, name)} != {getattr(actual, name)}"
        for name in ("nbody", "ngeom", "njnt", "nq", "nmesh", "ntex", "nmat")
        if getattr(expected, name) != getattr(actual, name)
    ]
    if problems:
        return problems
    for name in ("qpos0", "geom_size", "geom_pos", "body_mass"):
        if not np.allclose(getattr(expected, name), getattr(actual, name), atol=1e-6):
            problems.append(f"{name} differs")
    return problems


def _check_same(expected: mujoco.MjModel, actual: mujoco.MjModel, fmt: str) -> None:
    problems = model_differences(expected, actual)
    if problems:
        raise ExportError(f"the {fmt} package loads as another model: {'; '.join(problems)}")
