"""Import an objathor asset directory (the Objaverse assets Holodeck houses name) into a library.

Holodeck houses name Objaverse assets by their uid (32 hex digits) in ``objects[].assetId``.
Users of Holodeck keep those assets in an *objathor* directory; this module reads one and turns
each uid into a holomj asset **whose id is the uid**, so ``holomj compile house.json --library
LIB`` finds it (the ProcTHOR/Holodeck importer uses an ``assetId`` the library holds as is).

The layout (learnt from the public ``allenai/objathor`` package, ``objathor/dataset/``,
``objathor/asset_conversion/`` and ``objathor/annotation/``, and from ``allenai/Holodeck``'s
``ai2holodeck/constants.py`` and ``generation/utils.py``; this reader is our own)
------------------------------------------------------------------------------------------

``DIR`` is either a dataset version folder or its ``assets/`` folder::

    DIR/annotations.json.gz          all annotations, {uid: annotation} (gzip JSON; plain JSON
                                     is read too); absent when DIR is the assets folder itself,
                                     then DIR/../annotations.json.gz is used when DIR is named
                                     ``assets``
    DIR/assets/<uid>/                one folder per asset (or DIR/<uid>/):
        <uid>.pkl.gz                 the mesh dict, a gzip-compressed pickle (protocol 4); the
                                     conversion pipeline may also write <uid>.msgpack.gz,
                                     <uid>.msgpack, <uid>.json or <uid>.json.gz with the same dict
        albedo.jpg                   base colour (``albedoTexturePath``; .png before compression)
        normal.jpg, emission.jpg,    normal map, emission, metallic (R) / smoothness (B)
        metallic_smoothness.jpg      (not used: a MuJoCo material shows the colour texture only)
        annotations.json.gz          this asset's annotation (left out of the released tarball;
                                     used when the global file lacks the uid)
        thor_metadata.json           THOR's metadata (merged into the global annotations as
                                     ``thor_metadata``; left out of the tarball)
        <uid>.obj                    the converted mesh as OBJ, same frame as the dict (kept only
                                     when the conversion did not delete it); <uid>.glb, if
                                     present, is the original Objaverse glTF
        thor_renders/                THOR renders (not used)

Per-uid tar archives (``<uid>.tar``) are not read: extract them first.

The mesh dict (keys we read; the others, ``visibilityPoints``, ``physicalProperties``,
``annotations``, ``metallicSmoothnessTexturePath``, are ignored):

* ``vertices``: list of ``{"x", "y", "z"}`` (metres), one per face corner (Blender loops, so
  unwelded); ``triangles``: flat list of indices, three per triangle; ``uvs``: list of
  ``{"x", "y"}`` per vertex, origin bottom-left (Blender/Unity, the OBJ ``vt`` convention);
  ``normals``: per-vertex normals (not used; MuJoCo computes its own). Arrays of shape (N, 3)
  / (N, 2) / (M, 3) are accepted as well.
* ``colliders`` (optional): list of convex pieces ``{"vertices": [{x, y, z}...], "triangles":
  [flat indices]}`` from V-HACD, in the same frame as ``vertices``.
* ``yRotOffset`` (optional, degrees): a turn about the up axis THOR applies to the mesh when it
  creates the asset (objathor chooses it, within ±45°, to minimise the axis-aligned box; its
  sign is Unity's, clockwise seen from above). THOR's bounding box, and so every Holodeck
  footprint, includes it, so we apply it too.
* ``albedoTexturePath`` etc.: texture paths, relative to the asset folder or absolute (of the
  machine that converted it): only the file name is used, looked up in the asset folder.
* ``receptacleCandidate`` (optional bool): whether THOR may make the asset a receptacle.

Frame of the dict: THOR/Unity, **Y up**, left-handed, metres, already scaled to real size
(objathor scales in Blender to the annotation's ``scale``) and turned to its canonical pose
(``pose_z_rot_angle``), bottom at y = 0 and footprint centred on x = z = 0. The asset's
**front faces +z** (like every ProcTHOR asset at rotation 0). Triangles wind counter-clockwise
about the outward normal in the stored numbers (objathor mirrors x in Blender and flips the
normals back before export); the repair step re-orients closed bodies either way.

Annotations (fields read; all optional, wrong types are ignored with a warning): ``uid``,
``category`` (free text: "coffee table", "eames chair"), ``description`` (else
``description_auto``, else ``description_long``), ``height`` / ``width`` / ``depth`` (cm),
``mass`` (kg), ``receptacle`` (bool), ``onFloor`` / ``onWall`` / ``onObject`` / ``onCeiling``
(bools), ``synset`` (WordNet, e.g. ``straight_chair.n.01``), ``scale`` (metres: the height when
``z_axis_scale``, else the largest side) and ``pose_z_rot_angle`` (radians; both already applied
to the mesh dict, used only for a ``.glb``), ``license_info`` (``license``, ``uri``,
``creator_display_name``), and ``thor_metadata.assetMetadata.boundingBox`` (Unity axes, metres,
as ``{"min", "max"}``, ``{"x", "y", "z"}`` or ``{"size"}``; Holodeck's own database puts
``assetMetadata`` and ``annotations`` at the top level of an entry: read too).

Conversion
----------

A point ``v`` of the dict becomes ``a = M Ry(yRotOffset) v`` in the asset frame, with
``M = [[0, 0, 1], [-1, 0, 0], [0, 1, 0]]`` (asset ``+X`` = Unity ``+z``, the front; ``+Y`` =
Unity ``-x``; ``+Z`` = Unity ``+y``, up) and ``Ry`` Unity's turn about y. ``M`` is a reflection
(Unity is left-handed), so triangles are re-wound. This is the one choice that agrees with
:mod:`holomj.importers.frames`: an object at Unity rotation ``y`` is placed at holomj yaw
``90 - y``, and its mesh then lands where THOR draws it. The import itself (normalisation, repair,
colliders, surfaces, metadata, caching) is :mod:`asset_pipeline.objathor_import`.

An original ``.glb`` (glTF: Y up, right-handed, arbitrary units) is canonicalised as objathor
does it: Y-up to Z-up, ``pose_z_rot_angle`` about Z, scaled so its height (``z_axis_scale``) or
largest side is ``scale`` metres, then its front (Blender ``-Y``) turned to ``+X``.

Safety: pickles are loaded with a restricted unpickler that only builds plain containers
(dict, list, tuple, set), numbers, strings and numpy arrays/scalars: a pickle naming any other
class or function (the way pickles run code) is rejected with an error naming the file. A bad
file (corrupt gzip or pickle, wrong shapes, indices out of range) is a one-line
:class:`~holomj.errors.FormatError` naming it; missing optional files (texture, colliders,
annotations) are warnings.
"""

from __future__ import annotations

import dataclasses
import gzip
import io
import json
import math
import pickle
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np

from asset_pipeline.load import Material, Part
from holomj.errors import FormatError, InputError, closest_names
from holomj.spec.assets import PLACEMENTS

__all__ = [
    "ObjathorAnnotation",
    "ObjathorJob",
    "ObjathorMesh",
    "find_mesh_file",
    "gltf_to_asset",
    "load_pickle",
    "parse_annotation",
    "plan_objathor",
    "read_annotation_file",
    "read_mesh",
    "unity_to_asset",
    "unity_yaw",
]

ANNOTATION_FILES = ("annotations.json.gz", "annotations.json")
MESH_SUFFIXES = (".pkl.gz", ".pkl", ".msgpack.gz", ".msgpack", ".json.gz", ".json")
GEOMETRY_SUFFIXES = (".obj", ".glb", ".gltf")
ALBEDO_NAMES = ("albedo.jpg", "albedo.jpeg", "albedo.png")
MAX_DECOMPRESSED_BYTES = 1 << 30  # a mesh dict is a few MB; refuse gzip bombs
MAX_TEXTURE_PX = 2048
MAX_DESCRIPTION = 2000
ID_PATTERN = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.:|+\-]{0,127}$")

# Unity local (x right, y up, z front; left-handed) -> asset frame (X front, Y left, Z up).
UNITY_TO_ASSET = np.array([[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
# glTF (Y up, right-handed) -> Blender (Z up), as Blender's glTF importer converts.
_GLTF_TO_BLENDER = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


# -- safe pickle loading ---------------------------------------------------------------------
_SAFE_GLOBALS = frozenset(
    {
        ("builtins", "dict"),
        ("builtins", "list"),
        ("builtins", "tuple"),
        ("builtins", "set"),
        ("builtins", "frozenset"),
        ("builtins", "bytearray"),
        ("builtins", "complex"),
        ("collections", "OrderedDict"),
        ("_codecs", "encode"),  # bytes in protocol-2 pickles of numpy arrays
        ("numpy", "ndarray"),
        ("numpy", "dtype"),
        ("numpy.core.multiarray", "_reconstruct"),
        ("numpy._core.multiarray", "_reconstruct"),
        ("numpy.core.multiarray", "scalar"),
        ("numpy._core.multiarray", "scalar"),
        ("numpy.core.numeric", "_frombuffer"),
        ("numpy._core.numeric", "_frombuffer"),
    }
)


class _RestrictedUnpickler(pickle.Unpickler):
    """An unpickler that builds only plain containers and numpy arrays (no other globals)."""

    def find_class(self, module: str, name: str) -> Any:
        if (module, name) not in _SAFE_GLOBALS:
            raise pickle.UnpicklingError(f"the pickle names {module}.{name}")
        return super().find_class(module, name)


def load_pickle(path: Path) -> Any:
    """Load a (gzip-compressed or plain) pickle with the restricted unpickler.

    Raises :class:`FormatError` naming ``path`` for a corrupt file or a pickle that names any
    class or function beyond plain containers and numpy arrays.
    """
    raw = _read_maybe_gzip(path)
    try:
        return _RestrictedUnpickler(io.BytesIO(raw)).load()
    except pickle.UnpicklingError as err:
        text = str(err)
        if text.startswith("the pickle names"):
            raise FormatError(
                f"unsafe pickle refused: {text} (only plain containers and numpy arrays are "
                "loaded)",
                where=str(path),
                fix="re-export the asset with objathor, or convert it to .json",
            ) from None
        raise FormatError(f"corrupt pickle: {_short(err)}", where=str(path)) from None
    except Exception as err:  # any unpickling failure is a bad file
        raise FormatError(f"corrupt pickle: {_short(err)}", where=str(path)) from None


def _read_maybe_gzip(path: Path) -> bytes:
    """The bytes of ``path``, gunzipped when they start with the gzip magic number."""
    where = str(path)
    try:
        with open(path, "rb") as handle:
            head = handle.read(2)
            handle.seek(0)
            if head != b"\x1f\x8b":
                return handle.read()
            with gzip.GzipFile(fileobj=handle) as unzipped:
                data = unzipped.read(MAX_DECOMPRESSED_BYTES + 1)
    except FileNotFoundError:
        raise FormatError("file not found", where=where) from None
    except OSError as err:  # BadGzipFile is an OSError
        raise FormatError(f"cannot read the file: {_short(err)}", where=where) from None
    except (EOFError, ValueError) as err:  # truncated stream, zlib errors
        raise FormatError(f"corrupt gzip data: {_short(err)}", where=where) from None
    if len(data) > MAX_DECOMPRESSED_BYTES:
        raise FormatError("more than 1 GiB once decompressed", where=where)
    return data


def _short(err: BaseException) -> str:
    text = " ".join(str(err).split())[:200]
    return text or type(err).__name__


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
        number = _number(value)
        if number is None:
            self._bad(key, "a number")
        return number

    def positive(self, key: str) -> float | None:
        value = self.data.get(key)
        if value is None:
            return None
        number = _number(value)
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


def _number(value: Any) -> float | None:
    """A finite float from a number or a numeric string (GPT writes "175"); else None."""
    if isinstance(value, bool):
        return None
    if isinstance(value, str):
        try:
            value = float(value.strip())
        except ValueError:
            return None
    if not isinstance(value, (int, float)):
        return None
    try:
        number = float(value)
    except OverflowError:
        return None
    return number if math.isfinite(number) else None


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
                extents = tuple(h - lo_ for lo_, h in zip(lo, hi, strict=True))
        elif "x" in box:
            extents = _xyz(box)
        elif isinstance(box.get("size"), dict):
            extents = _xyz(box["size"])
    if extents is None or min(extents) <= 0:
        warnings.append(f"{where}: boundingBox ignored (not a box with positive extents)")
        return None
    return extents  # type: ignore[return-value]


def _xyz(value: dict) -> tuple[float, float, float] | None:
    numbers = [_number(value.get(k)) for k in "xyz"]
    if any(n is None for n in numbers):
        return None
    return tuple(numbers)  # type: ignore[return-value]


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
    data = _read_json(path)
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


def _read_json(path: Path) -> Any:
    raw = _read_maybe_gzip(path)
    try:
        return json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise FormatError("not UTF-8 JSON text", where=str(path)) from None
    except json.JSONDecodeError as err:
        raise FormatError(f"invalid JSON: {err}", where=str(path)) from None


# -- mesh files ------------------------------------------------------------------------------
@dataclass(frozen=True)
class ObjathorMesh:
    """One asset's geometry as read: parts and colliders in the source frame."""

    source: Path
    format: str  # pkl, msgpack, json, obj, glb, gltf
    frame: Literal["unity", "gltf"]
    parts: list[Part]
    colliders: list[np.ndarray] | None  # convex piece point sets, source frame; None: none
    y_rot_offset_deg: float = 0.0
    receptacle_candidate: bool | None = None
    texture: Path | None = None
    warnings: list[str] = field(default_factory=list)


def find_mesh_file(folder: Path, uid: str) -> Path | None:
    """The asset's mesh file in ``folder``: the dict (pickle, msgpack, JSON) first, then an
    OBJ (objathor's export), then the original glTF."""
    for suffix in MESH_SUFFIXES + GEOMETRY_SUFFIXES:
        candidate = folder / f"{uid}{suffix}"
        if candidate.is_file():
            return candidate
    return None


def read_mesh(path: Path, max_faces: int = 2_000_000) -> ObjathorMesh:
    """Read an asset's mesh file (see the module docstring); FormatError naming the file."""
    path = Path(path)
    name = path.name.lower()
    if name.endswith(GEOMETRY_SUFFIXES):
        return _read_geometry(path, max_faces)
    if name.endswith((".pkl.gz", ".pkl")):
        data, fmt = load_pickle(path), "pkl"
    elif name.endswith((".msgpack.gz", ".msgpack")):
        data, fmt = _load_msgpack(path), "msgpack"
    elif name.endswith((".json.gz", ".json")):
        data, fmt = _read_json(path), "json"
    else:
        raise FormatError(
            "not an objathor mesh file",
            where=str(path),
            fix=f"use one of {', '.join(MESH_SUFFIXES + GEOMETRY_SUFFIXES)}",
        )
    return _mesh_from_dict(data, path, fmt, max_faces)


def _load_msgpack(path: Path) -> Any:
    try:
        import msgpack
    except ImportError:
        raise FormatError(
            "reading .msgpack assets needs the msgpack package",
            where=str(path),
            fix="pip install msgpack",
        ) from None
    raw = _read_maybe_gzip(path)
    try:
        return msgpack.unpackb(raw, raw=False, strict_map_key=False)
    except Exception as err:  # any decoding failure is a bad file
        raise FormatError(f"corrupt msgpack data: {_short(err)}", where=str(path)) from None


def _mesh_from_dict(data: Any, path: Path, fmt: str, max_faces: int) -> ObjathorMesh:
    where = str(path)
    if not isinstance(data, dict):
        raise FormatError(f"expected a mesh dict, got {type(data).__name__}", where=where)
    warnings: list[str] = []
    vertices = _points(data.get("vertices"), 3, where, "vertices")
    faces = _faces(data.get("triangles"), len(vertices), where, "triangles")
    if len(faces) == 0:
        raise FormatError("the mesh has no triangles", where=where)
    if len(faces) > max_faces:
        raise FormatError(
            f"the mesh has {len(faces)} faces, more than the limit of {max_faces}", where=where
        )
    uv = None
    if data.get("uvs") is not None:
        try:
            uv = _points(data["uvs"], 2, where, "uvs")
        except FormatError as err:
            warnings.append(f"{err.one_line()}; texture dropped")
        if uv is not None and len(uv) != len(vertices):
            warnings.append(f"{where}: {len(uv)} uvs for {len(vertices)} vertices; texture dropped")
            uv = None
    texture_path = _texture_path(data.get("albedoTexturePath"), path.parent)
    material, uv = _material(texture_path, uv, warnings, path.parent)
    colliders = None
    if data.get("colliders") is not None:
        colliders = _colliders(data["colliders"], where, warnings)
    y_rot = _number(data.get("yRotOffset", 0.0))
    if y_rot is None:
        warnings.append(f"{where}: yRotOffset ignored (not a number)")
        y_rot = 0.0
    receptacle = data.get("receptacleCandidate")
    part = Part(vertices=vertices, faces=faces, uv=uv, material=material)
    return ObjathorMesh(
        source=path,
        format=fmt,
        frame="unity",
        parts=[part],
        colliders=colliders,
        y_rot_offset_deg=y_rot,
        receptacle_candidate=receptacle if isinstance(receptacle, bool) else None,
        texture=texture_path if material.texture_png is not None else None,
        warnings=warnings,
    )


def _points(value: Any, dims: int, where: str, name: str) -> np.ndarray:
    """An (N, dims) float array from a list of ``{x, y[, z]}`` dicts or an array-like."""
    keys = "xyz"[:dims]
    if value is None:
        raise FormatError(f"missing {name!r}", where=where)
    if isinstance(value, (list, tuple)) and value and isinstance(value[0], dict):
        rows = []
        for i, item in enumerate(value):
            row = [_number(item.get(k)) for k in keys] if isinstance(item, dict) else [None]
            if None in row:
                raise FormatError(f"{name}[{i}] must be {{{', '.join(keys)}}} numbers", where=where)
            rows.append(row)
        array = np.asarray(rows, dtype=np.float64)
    else:
        try:
            array = np.asarray(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise FormatError(f"{name!r} must hold numbers", where=where) from None
        if array.ndim == 1 and array.size % dims == 0:
            array = array.reshape(-1, dims)
        if array.ndim != 2 or array.shape[1] != dims:
            raise FormatError(
                f"{name!r} must be a list of {dims}-vectors, got shape {array.shape}",
                where=where,
            )
    if not np.isfinite(array).all():
        raise FormatError(f"{name!r} has NaN or infinite values", where=where)
    return array.reshape(-1, dims)


def _faces(value: Any, n_vertices: int, where: str, name: str) -> np.ndarray:
    """An (M, 3) index array from a flat list (three per triangle) or an (M, 3) array-like."""
    if value is None:
        raise FormatError(f"missing {name!r}", where=where)
    try:
        array = np.asarray(value)
    except (TypeError, ValueError):
        raise FormatError(f"{name!r} must be a list of indices", where=where) from None
    if array.size == 0:
        return np.zeros((0, 3), dtype=np.int64)
    whole = array.dtype.kind in "iu" or (
        array.dtype.kind == "f" and bool(np.array_equal(array, np.round(array)))
    )
    if not whole:
        raise FormatError(f"{name!r} must hold whole numbers", where=where)
    if array.size % 3 != 0:
        raise FormatError(f"{name!r} has {array.size} indices, not a multiple of 3", where=where)
    faces = array.astype(np.int64).reshape(-1, 3)
    if faces.min() < 0 or faces.max() >= n_vertices:
        raise FormatError(
            f"{name!r} indexes vertex {int(faces.max())} of {n_vertices} (out of range)",
            where=where,
        )
    return faces


def _colliders(value: Any, where: str, warnings: list[str]) -> list[np.ndarray] | None:
    """Point sets of the shipped convex pieces; bad pieces are skipped with a warning."""
    if not isinstance(value, (list, tuple)):
        warnings.append(f"{where}: colliders ignored (not a list)")
        return None
    pieces = []
    for i, piece in enumerate(value):
        try:
            if not isinstance(piece, dict):
                raise FormatError("not a {vertices, triangles} object", where=where)
            points = _points(piece.get("vertices"), 3, where, f"colliders[{i}].vertices")
        except FormatError as err:
            warnings.append(f"collider {i} skipped: {err.one_line()}")
            continue
        if len(points) >= 4:
            pieces.append(points)
    return pieces or None


def _texture_path(value: Any, folder: Path) -> Path | None:
    """The albedo texture in the asset folder: the dict's file name, else ``albedo.*``."""
    names = []
    if isinstance(value, str) and value:
        names.append(Path(value.replace("\\", "/")).name)
    names.extend(ALBEDO_NAMES)
    for name in names:
        if name and (folder / name).is_file():
            return folder / name
    return None


def _material(
    texture_path: Path | None, uv: np.ndarray | None, warnings: list[str], folder: Path
) -> tuple[Material, np.ndarray | None]:
    """A white textured material when the albedo texture and UVs are there, else grey."""
    grey = Material(rgba=(0.7, 0.7, 0.7, 1.0), name="objathor")
    if texture_path is None:
        warnings.append(f"{folder}: no albedo texture (albedo.jpg); the asset is plain grey")
        return grey, None
    if uv is None:
        warnings.append(f"{texture_path}: texture not used (the mesh has no UVs)")
        return grey, None
    png = _png(texture_path, warnings)
    if png is None:
        return grey, None
    return Material(rgba=(1.0, 1.0, 1.0, 1.0), texture_png=png, name="objathor"), uv


def _png(path: Path, warnings: list[str]) -> bytes | None:
    """An RGB PNG of an image file (at most MAX_TEXTURE_PX a side); None with a warning."""
    from PIL import Image, UnidentifiedImageError

    try:
        with Image.open(path) as image:
            image = image.convert("RGB")
            if max(image.size) > MAX_TEXTURE_PX:
                ratio = MAX_TEXTURE_PX / max(image.size)
                size = (max(1, round(image.size[0] * ratio)), max(1, round(image.size[1] * ratio)))
                image = image.resize(size, Image.Resampling.LANCZOS)
            buffer = io.BytesIO()
            image.save(buffer, format="PNG", compress_level=6)
    except (OSError, UnidentifiedImageError, ValueError) as err:
        warnings.append(f"{path}: unreadable texture ignored ({_short(err)})")
        return None
    return buffer.getvalue()


def _read_geometry(path: Path, max_faces: int) -> ObjathorMesh:
    """An OBJ (objathor's export, dict frame) or the original glTF, via the mesh loader."""
    from asset_pipeline.load import load_file

    loaded = load_file(path, max_faces)
    warnings = list(loaded.warnings)
    texture = _texture_path(None, path.parent)
    parts = list(loaded.parts)
    if all(p.material.texture_png is None for p in parts) and texture is not None:
        png = _png(texture, warnings)
        if png is not None and any(p.uv is not None for p in parts):
            material = Material(rgba=(1.0, 1.0, 1.0, 1.0), texture_png=png, name="objathor")
            parts = [
                dataclasses.replace(p, material=material) if p.uv is not None else p for p in parts
            ]
    frame: Literal["unity", "gltf"] = "gltf" if loaded.format in ("glb", "gltf") else "unity"
    return ObjathorMesh(
        source=path,
        format=loaded.format,
        frame=frame,
        parts=parts,
        colliders=None,
        texture=texture,
        warnings=warnings,
    )


# -- frames ----------------------------------------------------------------------------------
def unity_yaw(deg: float) -> np.ndarray:
    """Unity's ``Quaternion.Euler(0, deg, 0)`` as a matrix on Unity column vectors."""
    t = math.radians(deg)
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def unity_to_asset(y_rot_offset_deg: float = 0.0) -> np.ndarray:
    """The matrix taking a point of the mesh dict to the asset frame (see the docstring)."""
    return UNITY_TO_ASSET @ unity_yaw(y_rot_offset_deg)


def gltf_to_asset(parts: list[Part], annotation: ObjathorAnnotation) -> tuple[np.ndarray, float]:
    """(matrix, scale) canonicalising an original glTF as objathor does (module docstring)."""
    to_blender = _GLTF_TO_BLENDER
    points = np.concatenate([p.vertices for p in parts]) @ to_blender.T
    dims = points.max(axis=0) - points.min(axis=0)
    scale = 1.0
    if annotation.scale_m is not None:
        reference = dims[2] if annotation.z_axis_scale else dims.max()
        if reference > 1e-12:
            scale = annotation.scale_m / float(reference)
    angle = math.pi / 2 + annotation.pose_z_rot_rad  # pose, then Blender -Y (front) to +X
    c, s = math.cos(angle), math.sin(angle)
    turn = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return turn @ to_blender, scale


# -- a directory of assets -------------------------------------------------------------------
@dataclass(frozen=True)
class ObjathorJob:
    """One uid to import: its folder, mesh file and raw annotation (None when absent)."""

    uid: str
    folder: Path
    mesh_file: Path | None
    annotation: Any = None
    annotation_source: str | None = None
    id_note: str | None = None


def _assets_dir(root: Path) -> Path:
    return root / "assets" if (root / "assets").is_dir() else root


def _annotation_files(root: Path, assets: Path) -> list[Path]:
    """Global annotation files: in ``root``, or beside an ``assets`` folder given as DIR."""
    folders = [root]
    if assets == root and root.name == "assets":
        folders.append(root.parent)
    for folder in folders:
        found = [folder / n for n in ANNOTATION_FILES if (folder / n).is_file()]
        if found:
            return found[:1]
    return []


def plan_objathor(directory: Path | str, uids: Sequence[str] | None = None) -> list[ObjathorJob]:
    """The jobs for the assets of an objathor ``directory`` (only ``uids`` when given).

    Checks everything a job needs up front: the directory exists and holds asset folders,
    every asked uid has a folder, the global annotation file (if any) parses. Raises
    :class:`InputError` / :class:`FormatError` before anything is written.
    """
    root = Path(directory)
    if not root.is_dir():
        raise InputError("not a folder", where=str(root), fix="give the objathor asset folder")
    assets = _assets_dir(root)
    annotations: dict[str, Any] = {}
    sources: dict[str, str] = {}
    for path in _annotation_files(root, assets):
        for uid, entry in read_annotation_file(path).items():
            annotations[uid] = entry
            sources[uid] = str(path)
    folders = {
        p.name: p
        for p in sorted(assets.iterdir())
        if p.is_dir() and ID_PATTERN.match(p.name) and find_mesh_file(p, p.name) is not None
    }
    if uids:
        wanted = list(dict.fromkeys(u.strip() for u in uids if u.strip()))
        missing = [u for u in wanted if not (assets / u).is_dir()]
        if missing:
            near = closest_names(missing[0], folders)
            raise InputError(
                f"no asset folder for uid {missing[0]!r}",
                where=str(assets),
                fix=f"did you mean {near}?" if near else "see the uid folders of the directory",
            )
    else:
        wanted = sorted(folders)
        if not wanted:
            raise InputError(
                "no objathor assets found (no <uid>/<uid>.pkl.gz, .msgpack, .json, .obj or .glb)",
                where=str(assets),
                fix="give the dataset folder (with assets/) or its assets folder",
            )
    jobs = []
    for uid in wanted:
        folder = assets / uid
        annotation, source = annotations.get(uid), sources.get(uid)
        local = _local_annotation(folder)
        if local is not None:
            if annotation is None:
                annotation, source = local
            elif isinstance(annotation, dict) and isinstance(local[0], dict):
                annotation = {**local[0], **annotation}
                source = f"{source} + {local[1]}"
        jobs.append(
            ObjathorJob(
                uid=uid,
                folder=folder,
                mesh_file=find_mesh_file(folder, uid),
                annotation=annotation,
                annotation_source=source,
            )
        )
    return jobs


def _local_annotation(folder: Path) -> tuple[Any, str] | None:
    """The per-asset annotation file's entry, or None (a bad file is the job's error later)."""
    for name in ANNOTATION_FILES:
        path = folder / name
        if path.is_file():
            try:
                entries = read_annotation_file(path)
            except FormatError as err:
                return {"__error__": err.one_line()}, str(path)
            entry = entries.get(folder.name)
            if entry is None and len(entries) == 1:
                entry = next(iter(entries.values()))
            return entry, str(path)
    return None
