"""An objathor asset's mesh file (a pickled, msgpack or JSON mesh dict, or an OBJ/glTF file) and
the transforms from its frame to holomj's asset frame (see :mod:`asset_pipeline.objathor`)."""

from __future__ import annotations

import dataclasses
import io
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np

from asset_pipeline.load import MeshMaterial, MeshPart
from asset_pipeline.objathor_annotation import ObjathorAnnotation
from asset_pipeline.objathor_files import (
    ALBEDO_NAMES,
    GEOMETRY_SUFFIXES,
    MAX_TEXTURE_PX,
    MESH_SUFFIXES,
    finite_number,
    load_pickle,
    read_json,
    read_maybe_gzip,
    short_error,
)
from holomj.errors import FormatError

# Unity local (x right, y up, z front; left-handed) -> asset frame (X front, Y left, Z up).
UNITY_TO_ASSET = np.array([[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
# glTF (Y up, right-handed) -> Blender (Z up), as Blender's glTF importer converts.
_GLTF_TO_BLENDER = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


# -- mesh files ------------------------------------------------------------------------------
@dataclass(frozen=True)
class ObjathorMesh:
    """One asset's geometry as read: parts and colliders in the source frame."""

    source: Path
    format: str  # pkl, msgpack, json, obj, glb, gltf
    frame: Literal["unity", "gltf"]
    parts: list[MeshPart]
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
        data, fmt = read_json(path), "json"
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
    raw = read_maybe_gzip(path)
    try:
        return msgpack.unpackb(raw, raw=False, strict_map_key=False)
    except Exception as err:  # any decoding failure is a bad file
        raise FormatError(f"corrupt msgpack data: {short_error(err)}", where=str(path)) from None


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
    y_rot = finite_number(data.get("yRotOffset", 0.0))
    if y_rot is None:
        warnings.append(f"{where}: yRotOffset ignored (not a number)")
        y_rot = 0.0
    receptacle = data.get("receptacleCandidate")
    part = MeshPart(vertices=vertices, faces=faces, uv=uv, material=material)
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
            row = [finite_number(item.get(k)) for k in keys] if isinstance(item, dict) else [None]
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
) -> tuple[MeshMaterial, np.ndarray | None]:
    """A white textured material when the albedo texture and UVs are there, else grey."""
    grey = MeshMaterial(rgba=(0.7, 0.7, 0.7, 1.0), name="objathor")
    if texture_path is None:
        warnings.append(f"{folder}: no albedo texture (albedo.jpg); the asset is plain grey")
        return grey, None
    if uv is None:
        warnings.append(f"{texture_path}: texture not used (the mesh has no UVs)")
        return grey, None
    png = _png(texture_path, warnings)
    if png is None:
        return grey, None
    return MeshMaterial(rgba=(1.0, 1.0, 1.0, 1.0), texture_png=png, name="objathor"), uv


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
        warnings.append(f"{path}: unreadable texture ignored ({short_error(err)})")
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
            material = MeshMaterial(rgba=(1.0, 1.0, 1.0, 1.0), texture_png=png, name="objathor")
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


def gltf_to_asset(
    parts: list[MeshPart], annotation: ObjathorAnnotation
) -> tuple[np.ndarray, float]:
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
