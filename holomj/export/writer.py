"""Write a compiled scene as a self-contained folder, atomically.

Layout of ``OUT/``::

    scene.xml      MJCF with relative paths only (meshdir/texturedir = assets)
    scene.json     the SceneSpec (texture paths rewritten to point into assets/)
    assets/        every mesh and texture the model needs; also an asset library
                   (library.json + <asset>/asset.json) of the assets the scene uses
    *.json         extra reports handed in by the caller (e.g. import_report.json)

Everything is written into a temporary folder beside OUT and renamed into place at the end, so
a failure or a rejected input never leaves a half-written OUT behind.
"""

from __future__ import annotations

import json
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
) -> Path:
    """Write ``compiled`` to ``out`` (see module docstring) and return ``out``.

    ``extra_json`` and ``extra_text`` map file names in ``out`` to JSON data and to text, written
    in the same atomic step as the scene.
    """
    out = Path(out)
    prepare_output(out, overwrite)
    extras = {name: dump_json(data) for name, data in (extra_json or {}).items()}
    extras.update(extra_text or {})
    try:
        replace_folder(out, lambda tmp: _write_tree(compiled, tmp, extras))
    except OSError as err:
        raise ExportError(f"writing failed: {err}", where=str(out)) from None
    return out


def _write_tree(compiled: CompiledScene, root: Path, extras: dict[str, str]) -> None:
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
    for name, text in sorted(extras.items()):
        (root / name).write_text(text, encoding="utf-8")


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
