"""The output folder: the one module that knows its file names and reads and writes it.

Layout of ``OUT/``::

    scene.xml            MJCF with relative paths only (meshdir/texturedir = assets)
    scene.json           the SceneSpec (texture paths rewritten to point into assets/)
    assets/              every mesh and texture the model needs; also an asset library
                         (library.json + <asset>/asset.json) of the assets the scene uses
    objects.json         every object, door and the robot for task design
    navmap.json, .png    free floor grid and reachability from the entrance
    robot.json           the attached robot and where it stands (only with a robot)
    import_report.json   holomj compile: format, substitutions, warnings
    plan.json, generate.json, generate.log    holomj generate: plan, choices, stage log
    report.json          the validation report
    populate_report.json holomj populate: every placement outcome
    renders/, report.html  holomj render

The scene is written into a temporary folder beside OUT and renamed into place at the end, so a
failure or a rejected input never leaves a half-written OUT behind; single reports are replaced
atomically (:mod:`holomj.atomic`). Reading a folder back (scene, its own asset library, its
robot) for recompiling, validating, populating or rendering happens here too; the stages below
the jobs layer only see data in memory.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.atomic import replace_folder, write_file
from holomj.errors import ExportError, FormatError, InputError, OutputExistsError
from holomj.file_names import (
    ASSETS_DIR,
    LIBRARY_INDEX,
    LIBRARY_META,
    NAVMAP_JSON,
    NAVMAP_PNG,
    OBJECTS_JSON,
    ROBOT_JSON,
    SCENE_JSON,
    SCENE_XML,
)
from holomj.library.store import AssetLibrary
from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.mjcf.objects import Furniture
from holomj.physics.scene_io import LoadedScene, load_mjcf, loaded_from_compiled
from holomj.spec.base import read_json, validate_model
from holomj.spec.robot import RobotRecord
from holomj.spec.scene import SceneSpec
from holomj.spec.scene_file import read_scene_file

# written afresh with every export of the scene: everything else in a folder is a report about it
SCENE_FILES = frozenset(
    {SCENE_XML, SCENE_JSON, ASSETS_DIR, OBJECTS_JSON, NAVMAP_JSON, NAVMAP_PNG, ROBOT_JSON}
)


@dataclass(frozen=True)
class PreparedOutput:
    """An output folder :func:`prepare_output` checked: writing it needs no second check."""

    path: Path
    overwrite: bool


def prepare_output(out: Path, overwrite: bool) -> PreparedOutput:
    """Check, before any work, that ``out`` may be written; a one-line error naming what and
    where when not (exit code 2): it exists (without ``overwrite``) or is not a folder, or the
    folder it would be made in is a file, not writable, or refuses a new entry (``/proc``)."""
    out = Path(out)
    if out.exists() and not overwrite:
        raise OutputExistsError(
            "output folder exists", where=str(out), fix="pass --overwrite to replace it"
        )
    if out.exists() and not out.is_dir():
        raise OutputExistsError("output path exists and is not a folder", where=str(out))
    _check_writable_beside(out)
    return PreparedOutput(out, overwrite)


def _check_writable_beside(out: Path) -> None:
    """The nearest existing folder above ``out`` takes a new entry (tried: a temporary folder
    made and removed there)."""
    base = out.absolute().parent
    while not base.exists() and base != base.parent:
        base = base.parent
    fix = "choose an output folder in a writable place"
    if not base.is_dir():
        raise InputError(
            f"the output folder would be inside a file ({base})", where=str(out), fix=fix
        )
    if not os.access(base, os.W_OK | os.X_OK):
        raise InputError(f"cannot write into {base} (permission denied)", where=str(out), fix=fix)
    try:
        os.rmdir(tempfile.mkdtemp(prefix=f".{out.name}.check-", dir=base))
    except OSError as err:
        raise InputError(
            f"cannot write into {base} ({err.strerror or err})", where=str(out), fix=fix
        ) from None


def scene_for_export(scene: SceneSpec) -> SceneSpec:
    """The scene with material textures pointing at their copies under ``assets/``."""
    materials = {
        name: material.model_copy(update={"texture": f"{ASSETS_DIR}/{names.texture_file(name)}"})
        if material.texture
        else material
        for name, material in scene.materials.items()
    }
    return scene.model_copy(update={"materials": materials})


def dump_json(data: Any) -> str:
    """Deterministic, readable JSON text."""
    return json.dumps(data, indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def write_scene_folder(
    compiled: CompiledScene,
    out: Path | PreparedOutput,
    *,
    overwrite: bool = False,
    extra_json: dict[str, Any] | None = None,
    extra_text: dict[str, str] | None = None,
    keep_from: Path | None = None,
    finish: Callable[[Path], None] | None = None,
) -> Path:
    """Write ``compiled`` to ``out`` (see module docstring) and return ``out``.

    ``out``: a path (checked here with ``overwrite``) or what :func:`prepare_output` returned.
    ``extra_json`` and ``extra_text`` map file names in ``out`` to JSON data and to text, written
    in the same atomic step as the scene. ``keep_from``: a folder (usually ``out`` itself) whose
    other entries (reports, renders) are copied over unchanged. ``finish(tmp)`` runs last on the
    filled temporary folder, before it is renamed into place (it may add files: renders, a
    record of the whole run).
    """
    prepared = out if isinstance(out, PreparedOutput) else prepare_output(Path(out), overwrite)
    out = prepared.path
    extras: dict[str, str | bytes] = {
        name: dump_json(data) for name, data in (extra_json or {}).items()
    }
    extras.update(extra_text or {})
    extras.update(robot_learning_files(compiled))
    keep = _kept_entries(Path(keep_from), set(extras)) if keep_from is not None else []

    def fill(tmp: Path) -> None:
        _write_tree(compiled, tmp, extras)
        _copy_entries(keep, tmp)
        if finish is not None:
            finish(tmp)

    try:
        replace_folder(out, fill)
    except OSError as err:
        raise ExportError(f"writing failed: {err}", where=str(out)) from None
    return out


def robot_learning_files(compiled: CompiledScene) -> dict[str, str | bytes]:
    """``objects.json``, ``navmap.json``, ``navmap.png`` and (with a robot) ``robot.json``."""
    from holomj.jobs.robot_learning import build_navmap, objects_json

    navmap = build_navmap(compiled)
    files: dict[str, str | bytes] = {
        OBJECTS_JSON: dump_json(objects_json(compiled)),
        NAVMAP_JSON: dump_json(navmap.to_json()),
        NAVMAP_PNG: navmap.to_png(),
    }
    if compiled.robot is not None:
        files[ROBOT_JSON] = dump_json(compiled.robot.model_dump(mode="json"))
    return files


def _kept_entries(folder: Path, written: set[str]) -> list[Path]:
    """Entries of an earlier export of ``folder`` that this export does not write itself."""
    if not folder.is_dir():
        return []
    own = SCENE_FILES | written
    return sorted(p for p in folder.iterdir() if p.name not in own and not p.name.startswith("."))


def _copy_entries(entries: list[Path], root: Path) -> None:
    for entry in entries:
        if entry.is_dir():
            shutil.copytree(entry, root / entry.name, symlinks=True)
        else:
            shutil.copy2(entry, root / entry.name)


def _write_tree(compiled: CompiledScene, root: Path, extras: dict[str, str | bytes]) -> None:
    (root / SCENE_XML).write_text(compiled.to_xml(), encoding="utf-8")
    scene = scene_for_export(compiled.scene)
    (root / SCENE_JSON).write_text(
        dump_json(scene.model_dump(mode="json", exclude_none=True)), encoding="utf-8"
    )
    for relative, data in compiled.files.items():
        target = root / ASSETS_DIR / relative
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
    _write_asset_library(compiled, root / ASSETS_DIR)
    for name, content in sorted(extras.items()):
        if isinstance(content, bytes):
            (root / name).write_bytes(content)
        else:
            (root / name).write_text(content, encoding="utf-8")


def _write_asset_library(compiled: CompiledScene, assets_dir: Path) -> None:
    """Make ``assets/`` an asset library of the assets the scene uses (without thumbnails), so
    the folder can be recompiled, validated with free furniture or populated on its own."""
    index = {}
    for asset_id, asset in compiled.assets.items():
        folder = names.asset_folder(asset_id)
        meta = asset.meta.model_copy(update={"thumbnails": []})
        target = assets_dir / folder / LIBRARY_META
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(dump_json(meta.model_dump(mode="json")), encoding="utf-8")
        index[asset_id] = folder
    assets_dir.mkdir(parents=True, exist_ok=True)
    library = {"schema_version": "1.0", "name": f"{compiled.scene.name} assets", "assets": index}
    (assets_dir / LIBRARY_INDEX).write_text(dump_json(library), encoding="utf-8")


def write_report(folder: Path, name: str, data: Any) -> Path:
    """Replace one JSON report (``name``) of ``folder`` atomically; returns its path."""
    path = Path(folder) / name
    try:
        write_file(path, dump_json(data))
    except OSError as err:
        raise ExportError(f"cannot write: {err.strerror or err}", where=str(path)) from None
    return path


def write_json_file(path: Path, data: Any) -> None:
    """Write JSON to any ``path`` atomically ('-': standard output), for ``--json FILE``."""
    text = dump_json(data)
    if str(path) == "-":
        import sys

        sys.stdout.write(text)
        return
    path = Path(path)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        write_file(path, text)
    except OSError as err:
        raise InputError(f"cannot write: {err.strerror or err}", where=str(path)) from None


def scene_folder(path: Path) -> Path | None:
    """The holomj output folder ``path`` names (the folder or its scene.xml), else None."""
    path = Path(path)
    folder = path if path.is_dir() else path.parent
    is_scene = (folder / SCENE_JSON).is_file() and (folder / ASSETS_DIR / LIBRARY_INDEX).is_file()
    return folder if is_scene and (path.is_dir() or path.name == SCENE_XML) else None


def require_scene_folder(path: Path, command: str = "holomj compile") -> Path:
    """``path`` when it is a holomj output folder; else a one-line error naming it."""
    folder = scene_folder(path)
    if folder is None or folder != Path(path):
        raise InputError(
            "not a holomj scene folder (no scene.json and assets/library.json)",
            where=str(path),
            fix=f"pass a folder written by '{command}'",
        )
    return folder


def read_scene(folder: Path) -> SceneSpec:
    """The folder's ``scene.json``."""
    return read_scene_file(Path(folder) / SCENE_JSON)


def open_library(folder: Path) -> AssetLibrary:
    """The folder's own asset library (``assets/``)."""
    return AssetLibrary.open(Path(folder) / ASSETS_DIR)


def read_json_report(folder: Path, name: str) -> Any | None:
    """A JSON report of ``folder`` (None when absent); a one-line error when unreadable."""
    path = Path(folder) / name
    return read_json(path) if path.is_file() else None


def read_robot(folder: Path) -> RobotRecord | None:
    """The folder's ``robot.json`` (None when it has no robot)."""
    path = Path(folder) / ROBOT_JSON
    if not path.is_file():
        return None
    return validate_model(RobotRecord, read_json(path), str(path))


def attach_folder_robot(compiled: CompiledScene, folder: Path) -> CompiledScene:
    """``compiled`` with the robot ``folder`` was exported with (``robot.json`` and the robot's
    files under ``assets/``); unchanged when the folder has none."""
    from holomj.robots.attach import attach_recorded

    record = read_robot(folder)
    if record is None:
        return compiled
    assets = Path(folder) / ASSETS_DIR
    xml_path = Path(folder) / record.xml
    try:
        xml = xml_path.read_text(encoding="utf-8")
    except OSError as err:
        raise FormatError(
            f"cannot read the robot MJCF: {err.strerror or err}", where=str(xml_path)
        ) from None
    files = {
        path.relative_to(assets).as_posix(): path.read_bytes()
        for path in sorted((assets / "robot").rglob("*"))
        if path.is_file()
    }
    return attach_recorded(compiled, record, xml, files, where=str(xml_path))


def compile_folder(
    folder: Path, *, furniture: Furniture = "as-is", library: AssetLibrary | None = None
) -> CompiledScene:
    """Recompile the scene of ``folder`` from its ``scene.json`` and own library (or
    ``library``), with its robot."""
    scene = read_scene(folder)
    library = library or open_library(folder)
    compiled = compile_scene(scene, library, furniture=furniture)
    return attach_folder_robot(compiled, folder)


def load_for_physics(
    path: Path, *, furniture: Furniture = "free", library: AssetLibrary | None = None
) -> LoadedScene:
    """``path`` (a holomj folder, its scene.xml, or any MJCF file) ready to simulate: a holomj
    folder is recompiled from its scene (so furniture can be freed) with its robot; any other
    MJCF file is loaded as it is (:class:`holomj.physics.scene_io.LoadedScene`)."""
    path = Path(path)
    if not path.exists():
        raise FormatError("not found", where=str(path))
    folder = scene_folder(path)
    if folder is not None:
        library = library or open_library(folder)
        compiled = compile_folder(folder, furniture=furniture, library=library)
        return loaded_from_compiled(compiled, library, path, folder)
    if path.is_dir():
        raise FormatError(
            "not a holomj scene folder (no scene.json and assets/library.json)",
            where=str(path),
            fix="pass a folder written by 'holomj compile' or an MJCF file",
        )
    return load_mjcf(path)
