"""An objathor asset's annotation (its category, description, size, placement, mass, license):
what holomj reads of it and how (see :mod:`asset_pipeline.objathor`)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from asset_pipeline.objathor_files import (
    MAX_DESCRIPTION,
    finite_number,
    read_json,
)
from holomj.errors import FormatError
from holomj.spec.assets import PLACEMENTS


# -- annotations -----------------------------------------------------------------------------
@dataclass(frozen=True)
class ObjathorAnnotation:
    """The annotation fields we use, checked (``None`` where absent or unusable)."""

    uid: str | None = None
    category: str | None = None
    synset: str | None = None
    description: str | None = None
    height_m: float | None = None
    width_m: float | None = None
    depth_m: float | None = None
    mass_kg: float | None = None
    placement: tuple[str, ...] | None = None
    receptacle: bool | None = None
    scale_m: float | None = None
    z_axis_scale: bool = True
    pose_z_rot_rad: float = 0.0
    bbox_unity_m: tuple[float, float, float] | None = None  # THOR box extents, Unity x, y, z
    license: str | None = None
    attribution: str | None = None
    warnings: tuple[str, ...] = ()

    def as_report(self) -> dict[str, Any]:
        """JSON-able form for ``derivation.json``."""
        data = dataclasses.asdict(self)
        data.pop("warnings")
        return data


_FLAGS = {"onFloor": "floor", "onWall": "wall", "onObject": "object", "onCeiling": "ceiling"}


def parse_annotation(raw: Any, where: str) -> ObjathorAnnotation:
    """Check one annotation entry; a field of the wrong type is ignored with a warning.

    Raises :class:`FormatError` naming ``where`` only when ``raw`` is not a mapping.
    """
    if not isinstance(raw, dict):
        raise FormatError(
            f"an annotation must be a JSON object, got {type(raw).__name__}", where=where
        )
    warnings: list[str] = []
    data = dict(raw)
    nested = data.get("annotations")
    if isinstance(nested, dict):  # Holodeck's database: {"annotations": {...}, ...}
        data = {**data, **nested}
    reader = _FieldReader(data, where, warnings)
    flags = {name: reader.boolean(key) for key, name in _FLAGS.items()}
    placement: tuple[str, ...] | None = tuple(p for p in PLACEMENTS if flags.get(p))
    if not placement:
        if any(v is False for v in flags.values()):
            warnings.append(f"{where}: no placement flag is true; the category's default is used")
        placement = None
    description = None
    for key in ("description", "description_auto", "description_long"):
        description = reader.text(key, MAX_DESCRIPTION)
        if description:
            break
    scale = reader.positive("scale")
    z_axis_scale = reader.boolean("z_axis_scale")
    license_name, attribution = _license(data.get("license_info"))
    return ObjathorAnnotation(
        uid=reader.text("uid", 128),
        category=reader.text("category", 200),
        synset=reader.text("synset", 200),
        description=description,
        height_m=_cm(reader.positive("height")),
        width_m=_cm(reader.positive("width")),
        depth_m=_cm(reader.positive("depth")),
        mass_kg=reader.positive("mass"),
        placement=placement,
        receptacle=reader.boolean("receptacle"),
        scale_m=scale,
        z_axis_scale=True if z_axis_scale is None else z_axis_scale,
        pose_z_rot_rad=reader.finite("pose_z_rot_angle") or 0.0,
        bbox_unity_m=_bounding_box(data, where, warnings),
        license=license_name,
        attribution=attribution,
        warnings=tuple(warnings),
    )


class _FieldReader:
    """Typed reads of an annotation's fields; a bad value is a warning and reads as None."""

    def __init__(self, data: dict, where: str, warnings: list[str]) -> None:
        self.data, self.where, self.warnings = data, where, warnings

    def _bad(self, key: str, expected: str) -> None:
        value = repr(self.data[key])
        value = value if len(value) <= 40 else value[:37] + "..."
        self.warnings.append(f"{self.where}: {key} ignored (expected {expected}, got {value})")

    def text(self, key: str, limit: int) -> str | None:
        value = self.data.get(key)
        if value is None:
            return None
        if not isinstance(value, str):
            self._bad(key, "text")
            return None
        text = " ".join(value.split())
        return text[:limit] or None

    def finite(self, key: str) -> float | None:
        value = self.data.get(key)
        if value is None:
            return None
        number = finite_number(value)
        if number is None:
            self._bad(key, "a number")
        return number

    def positive(self, key: str) -> float | None:
        value = self.data.get(key)
        if value is None:
            return None
        number = finite_number(value)
        if number is None or number <= 0:
            self._bad(key, "a positive number")
            return None
        return number

    def boolean(self, key: str) -> bool | None:
        value = self.data.get(key)
        if value is None:
            return None
        if isinstance(value, bool):
            return value
        if isinstance(value, int) and value in (0, 1):
            return bool(value)
        if isinstance(value, str) and value.strip().lower() in _BOOL_TEXT:
            return _BOOL_TEXT[value.strip().lower()]
        self._bad(key, "true or false")
        return None


_BOOL_TEXT = {"true": True, "yes": True, "1": True, "false": False, "no": False, "0": False}


def _cm(value: float | None) -> float | None:
    return None if value is None else value / 100.0


def _bounding_box(data: dict, where: str, warnings: list[str]) -> tuple[float, float, float] | None:
    """THOR's axis-aligned box extents (Unity x, y, z) from ``thor_metadata`` or
    ``assetMetadata`` (Holodeck's ``get_bbox_dims``: min/max, x/y/z or size)."""
    meta = data.get("assetMetadata")
    thor = data.get("thor_metadata")
    if not isinstance(meta, dict) and isinstance(thor, dict):
        meta = thor.get("assetMetadata")
    if not isinstance(meta, dict) or "boundingBox" not in meta:
        return None
    box = meta["boundingBox"]
    extents = None
    if isinstance(box, dict):
        if isinstance(box.get("min"), dict) and isinstance(box.get("max"), dict):
            lo, hi = _xyz(box["min"]), _xyz(box["max"])
            if lo is not None and hi is not None:
                ex, ey, ez = (h - low for low, h in zip(lo, hi, strict=True))
                extents = (ex, ey, ez)
        elif "x" in box:
            extents = _xyz(box)
        elif isinstance(box.get("size"), dict):
            extents = _xyz(box["size"])
    if extents is None or min(extents) <= 0:
        warnings.append(f"{where}: boundingBox ignored (not a box with positive extents)")
        return None
    return extents


def _xyz(value: dict) -> tuple[float, float, float] | None:
    x, y, z = (finite_number(value.get(k)) for k in "xyz")
    if x is None or y is None or z is None:
        return None
    return (x, y, z)


def _license(info: Any) -> tuple[str | None, str | None]:
    if not isinstance(info, dict):
        return None, None
    name = info.get("license")
    license_name = f"objaverse/sketchfab: {name}" if isinstance(name, str) and name else None
    who = info.get("creator_display_name") or info.get("creator_username")
    uri = info.get("uri")
    parts = [str(p) for p in (who, uri) if isinstance(p, str) and p]
    return license_name, (", ".join(parts)[:500] or None)


def read_annotation_file(path: Path) -> dict[str, Any]:
    """The raw annotations of a file, by uid: ``{uid: entry}``, a single entry with a
    ``uid``, or a list of such entries; gzip or plain JSON. FormatError naming the file."""
    where = str(path)
    data = read_json(path)
    if isinstance(data, list):
        out = {}
        for i, entry in enumerate(data):
            if not isinstance(entry, dict) or not isinstance(entry.get("uid"), str):
                raise FormatError(f"entry [{i}] has no uid", where=where)
            out[entry["uid"]] = entry
        return out
    if not isinstance(data, dict):
        raise FormatError("expected a JSON object of annotations by uid", where=where)
    if isinstance(data.get("uid"), str):
        return {data["uid"]: data}
    return data
