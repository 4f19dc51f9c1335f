"""Recognising an input file's format and loading it as a holomj scene.

* holomj ``scene.json``: ``schema_version`` and ``rooms`` whose entries have ``polygon``.
* ProcTHOR / Holodeck house: ``rooms`` whose entries have ``floorPolygon``.
* 3D-Generalist SceneDef: a ``scenedef`` marker, a single ``room``, rooms with ``floor`` or
  ``bbox``, or objects with ``placements``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

from holomj.errors import FormatError, InputError
from holomj.importers.common import check_assets
from holomj.importers.procthor import import_procthor
from holomj.importers.result import ImportResult
from holomj.importers.scenedef import import_scenedef
from holomj.library.store import AssetLibrary
from holomj.spec.base import read_json, validate_model
from holomj.spec.scene import SceneSpec
from holomj.spec.scene_file import resolve_textures

Format = Literal["holomj", "procthor", "scenedef"]
FORMATS = ("holomj", "procthor", "holodeck", "scenedef")


def _first_items(value: Any) -> list[dict[str, Any]]:
    if isinstance(value, list):
        return [item for item in value if isinstance(item, dict)]
    return []


def detect_format(data: Any, source: str = "input") -> Format:
    """The format of a parsed JSON document, or a FormatError saying what we looked for."""
    if not isinstance(data, dict):
        raise FormatError(
            "expected a JSON object at the top level", where=source, fix=_formats_hint()
        )
    rooms = _first_items(data.get("rooms"))
    if "schema_version" in data and any("polygon" in r for r in rooms):
        return "holomj"
    if any("floorPolygon" in r for r in rooms):
        return "procthor"
    objects = _first_items(data.get("objects"))
    if (
        "scenedef" in data
        or isinstance(data.get("room"), dict)
        or any("floor" in r or "bbox" in r for r in rooms)
        or any("placements" in o for o in objects)
    ):
        return "scenedef"
    if "schema_version" in data and rooms:
        return "holomj"
    _refuse_old_thor_layout(data, objects, source)
    raise FormatError("not a format holomj knows", where=source, fix=_formats_hint())


_OLD_THOR_KEYS = ("sceneName", "walls", "doors", "windows", "proceduralParameters", "agent")


def _refuse_old_thor_layout(
    data: dict[str, Any], objects: list[dict[str, Any]], source: str
) -> None:
    """An AI2-THOR layout from before ProcTHOR (iTHOR scene metadata, or a house without
    rooms): refused in one line naming what holomj needs and it lacks."""
    thor_objects = any("objectId" in o or "objectType" in o or "assetId" in o for o in objects)
    if not (thor_objects or any(k in data for k in _OLD_THOR_KEYS)):
        return
    missing = "'rooms'" if "rooms" not in data else "'rooms[].floorPolygon'"
    raise FormatError(
        f"an AI2-THOR layout without {missing}: holomj builds a house from its rooms' floor "
        "polygons, which this older layout does not give",
        where=source,
        fix="export the house in ProcTHOR's schema (rooms with floorPolygon, walls, doors, "
        "windows, objects), or force a format with --format",
    )


def _formats_hint() -> str:
    return (
        "expected a holomj scene.json (schema_version + rooms[].polygon), a ProcTHOR/Holodeck "
        "house (rooms[].floorPolygon) or a 3D-Generalist SceneDef (objects[].placements); "
        "or force one with --format holomj|procthor|holodeck|scenedef"
    )


def load_scene_input(path: Path, library: AssetLibrary, fmt: str | None = None) -> ImportResult:
    """Read ``path`` and return the scene it describes, importing foreign formats.

    ``fmt`` forces a format: ``holomj``, ``procthor``, ``holodeck`` (the same importer as
    ``procthor``) or ``scenedef``; None detects it. Every object's asset must be in
    ``library``.
    """
    if fmt is not None and fmt not in FORMATS:
        raise InputError(
            f"unknown format {fmt!r}", where="--format", fix=f"use one of: {', '.join(FORMATS)}"
        )
    path = Path(path)
    source = str(path)
    data = read_json(path)
    chosen = fmt if fmt is not None else detect_format(data, source)
    if chosen in ("procthor", "holodeck"):
        return import_procthor(data, library, source)
    if chosen == "scenedef":
        return import_scenedef(data, library, source)
    return _load_holomj(data, path, library)


def _load_holomj(data: Any, path: Path, library: AssetLibrary) -> ImportResult:
    source = str(path)
    scene = validate_model(SceneSpec, data, source)
    scene = resolve_textures(scene, path.parent, source)
    check_assets(scene, library, source)
    return ImportResult(scene=scene, format="holomj")
