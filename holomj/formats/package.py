"""Single-file packages of a scene folder, in memory: MuJoCo's binary model and a zip archive.

- ``mjb``: :func:`model_mjb` is the compiled model as MuJoCo saves it (``mj_saveModel``); it
  loads with ``mujoco.MjModel.from_binary_path`` without parsing XML or meshes again.
- ``zip``: :func:`folder_zip` holds ``scene.xml`` and every file of the folder it may reference
  (meshes, textures, included XML), paths relative to the folder. It loads by extracting it, or
  straight from its bytes with ``mujoco.MjModel.from_xml_string(xml, assets=...)``.

:func:`load_package` takes either (or a folder, or its ``scene.xml``) and returns the model.
"""

from __future__ import annotations

import io
import re
import zipfile
from collections.abc import Iterable
from pathlib import Path

import mujoco
import numpy as np

from holomj.errors import FormatError, InputError
from holomj.file_names import SCENE_XML

PACKAGE_SUFFIXES = (".mjb", ".zip")
# folders of a scene folder the model never reads (renders, earlier exports, logs)
SKIPPED_FOLDERS = ("export", "renders", "logs", "__pycache__")
SKIPPED_SUFFIXES = (".png", ".jpg", ".jpeg", ".mp4", ".log", ".mjb", ".zip", ".glb", ".usdz")
_MODEL_SUFFIXES = (".png", ".jpg", ".jpeg")  # texture files are kept when the XML names them
_FILE_ATTRIBUTE = re.compile(r'\bfile="([^"]+)"')


def model_mjb(model: mujoco.MjModel) -> bytes:
    """The binary model file (``.mjb``) of ``model``."""
    buffer = np.zeros(mujoco.mj_sizeModel(model), dtype=np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return buffer.tobytes()


def folder_files(folder: Path) -> list[Path]:
    """The files of ``folder`` a zip package carries: everything but renders, logs, earlier
    exports and pictures the XML does not name (paths relative to ``folder``, sorted)."""
    folder = Path(folder)
    xml_text = (folder / SCENE_XML).read_text()
    chosen = []
    for path in sorted(folder.rglob("*")):
        if not path.is_file():
            continue
        relative = path.relative_to(folder)
        if relative.parts[0] in SKIPPED_FOLDERS or path.name.startswith("."):
            continue
        suffix = path.suffix.lower()
        if suffix in SKIPPED_SUFFIXES and not (suffix in _MODEL_SUFFIXES and path.name in xml_text):
            continue
        chosen.append(relative)
    return chosen


def folder_zip(folder: Path, files: Iterable[Path] | None = None) -> bytes:
    """A zip archive of the scene ``folder`` (``files``: relative paths; default
    :func:`folder_files`). Meshes and XML are deflated, pictures stored."""
    folder = Path(folder)
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        for relative in files if files is not None else folder_files(folder):
            stored = relative.suffix.lower() in _MODEL_SUFFIXES
            archive.write(
                folder / relative,
                relative.as_posix(),
                compress_type=zipfile.ZIP_STORED if stored else zipfile.ZIP_DEFLATED,
            )
    return buffer.getvalue()


def zip_model(data: bytes, where: str = "zip") -> mujoco.MjModel:
    """The model of a zip package's bytes, compiled from its ``scene.xml`` with the other
    members as MuJoCo assets (nothing is extracted)."""
    try:
        with zipfile.ZipFile(io.BytesIO(data)) as archive:
            members = {name: archive.read(name) for name in archive.namelist()}
    except zipfile.BadZipFile as err:
        raise FormatError(f"not a zip archive: {err}", where=where) from None
    xml = members.pop(SCENE_XML, None)
    if xml is None:
        raise FormatError(f"the archive has no {SCENE_XML}", where=where)
    text, assets = _flat_assets(xml.decode(), members, where)
    try:
        return mujoco.MjModel.from_xml_string(text, assets=assets)
    except ValueError as err:
        raise FormatError(
            f"MuJoCo cannot load it: {' '.join(str(err).split())}", where=where
        ) from None


def _flat_assets(xml: str, members: dict[str, bytes], where: str) -> tuple[str, dict[str, bytes]]:
    """The XML with every ``file="dir/name"`` made one unique flat name, and those names'
    bytes: MuJoCo's asset dictionary keys files by their base name only, and two assets'
    meshes often share one (``hull_00.obj``)."""
    assets: dict[str, bytes] = {}

    def flatten(match: re.Match[str]) -> str:
        named = match.group(1)
        flat = named.replace("/", "__")
        if flat not in assets:
            found = [path for path in members if path == named or path.endswith("/" + named)]
            if not found:
                raise FormatError(f"the archive has no file {named!r}", where=where)
            assets[flat] = members[min(found, key=len)]
        return f'file="{flat}"'

    return _FILE_ATTRIBUTE.sub(flatten, xml), assets


def load_package(path: Path | str) -> mujoco.MjModel:
    """The MuJoCo model of a scene package: a ``.mjb`` file, a ``.zip`` archive, a scene folder
    or its ``scene.xml``. A missing path is an InputError, an unreadable file a FormatError."""
    path = Path(path)
    if path.is_dir():
        path = path / SCENE_XML
    if not path.is_file():
        raise InputError("no such file", where=str(path), fix="name a .mjb, .zip or scene folder")
    suffix = path.suffix.lower()
    try:
        if suffix == ".mjb":
            return mujoco.MjModel.from_binary_path(str(path))
        if suffix == ".zip":
            return zip_model(path.read_bytes(), where=str(path))
        if suffix == ".xml":
            return mujoco.MjModel.from_xml_path(str(path))
    except ValueError as err:
        raise FormatError(
            f"MuJoCo cannot load it: {' '.join(str(err).split())}", where=str(path)
        ) from None
    raise InputError(
        f"unknown package type {suffix or '(none)'!r}",
        where=str(path),
        fix="name a .mjb or .zip package (holomj pack), a scene folder or scene.xml",
    )
