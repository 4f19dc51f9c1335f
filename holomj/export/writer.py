"""Write a compiled scene as a self-contained folder, atomically.

Layout of ``OUT/``::

    scene.xml      MJCF with relative paths only (meshdir/texturedir = assets)
    scene.json     the SceneSpec (texture paths rewritten to point into assets/)
    assets/        every mesh and texture the model needs; also an asset library
                   (library.json + <asset>/asset.json) of the assets the scene uses
    *.json         extra reports handed in by the caller (e.g. import_report.json)
    objects.json   every object, door and the robot for task design (export/objects_json.py)
    navmap.json    free floor grid and reachability from the entrance, and navmap.png
    robot.json     the attached robot and where it stands (only with a robot)

Everything is written into a temporary folder beside OUT and renamed into place at the end, so
a failure or a rejected input never leaves a half-written OUT behind.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

from holomj.atomic import replace_folder
from holomj.errors import ExportError, OutputExistsError
from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene
from holomj.spec.scene import SceneSpec

SCENE_XML = "scene.xml"
SCENE_JSON = "scene.json"
ASSETS_DIR = "assets"
LIBRARY_INDEX = "library.json"
LIBRARY_META = "asset.json"


def prepare_output(out: Path, overwrite: bool) -> None:
    """Check, before any work, that ``out`` may be written."""
    if out.exists() and not overwrite:
        raise OutputExistsError(
            "output folder exists", where=str(out), fix="pass --overwrite to replace it"
        )
    if out.exists() and not out.is_dir():
        raise OutputExistsError("output path exists and is not a folder", where=str(out))


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


def export_scene(
    compiled: CompiledScene,
    out: Path,
    *,
    overwrite: bool = False,
    extra_json: dict[str, Any] | None = None,
    extra_text: dict[str, str] | None = None,
    keep_from: Path | None = None,
) -> Path:
    """Write ``compiled`` to ``out`` (see module docstring) and return ``out``.

    ``extra_json`` and ``extra_text`` map file names in ``out`` to JSON data and to text, written
    in the same atomic step as the scene. ``keep_from``: a folder (usually ``out`` itself) whose
    other entries (reports, renders) are copied over unchanged.
    """
    out = Path(out)
    prepare_output(out, overwrite)
    extras: dict[str, str | bytes] = {
        name: dump_json(data) for name, data in (extra_json or {}).items()
    }
    extras.update(extra_text or {})
    extras.update(robot_learning_files(compiled))
    keep = _kept_entries(Path(keep_from), set(extras)) if keep_from is not None else []

    def fill(tmp: Path) -> None:
        _write_tree(compiled, tmp, extras)
        _copy_entries(keep, tmp)

    try:
        replace_folder(out, fill)
    except OSError as err:
        raise ExportError(f"writing failed: {err}", where=str(out)) from None
    return out


def robot_learning_files(compiled: CompiledScene) -> dict[str, str | bytes]:
    """``objects.json``, ``navmap.json``, ``navmap.png`` and (with a robot) ``robot.json``."""
    from holomj.export.navmap import NAVMAP_JSON, NAVMAP_PNG, build_navmap
    from holomj.export.objects_json import OBJECTS_JSON, objects_record
    from holomj.robots.records import ROBOT_JSON

    navmap = build_navmap(compiled)
    files: dict[str, str | bytes] = {
        OBJECTS_JSON: dump_json(objects_record(compiled)),
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
    from holomj.export.navmap import NAVMAP_JSON, NAVMAP_PNG
    from holomj.export.objects_json import OBJECTS_JSON
    from holomj.robots.records import ROBOT_JSON

    own = {SCENE_XML, SCENE_JSON, ASSETS_DIR, OBJECTS_JSON, NAVMAP_JSON, NAVMAP_PNG, ROBOT_JSON}
    own |= written
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
