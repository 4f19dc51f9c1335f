"""Read one mesh file (GLB, glTF, OBJ, STL, PLY) into flat parts with one material each.

Scene graphs are flattened with their node transforms (``Scene.dump``). Each part keeps its
base colour and, when it has UVs, its base-colour texture (re-encoded as an RGB PNG, at most
:data:`MAX_TEXTURE_PX` on a side). Everything that can go wrong with the file itself becomes a
one-line :class:`~holomj.errors.FormatError` naming the file.
"""

from __future__ import annotations

import hashlib
import io
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from holomj.errors import FormatError

FORMATS = {".glb": "glb", ".gltf": "gltf", ".obj": "obj", ".stl": "stl", ".ply": "ply"}
MAX_TEXTURE_PX = 2048


@dataclass(frozen=True)
class MeshMaterial:
    """What MuJoCo can show of a material: a colour and an optional PNG texture."""

    rgba: tuple[float, float, float, float]
    texture_png: bytes | None = None
    name: str = ""

    @property
    def key(self) -> tuple:
        """Parts with equal keys share one visual mesh."""
        digest = hashlib.sha256(self.texture_png).hexdigest() if self.texture_png else ""
        return (self.rgba, digest)


@dataclass(frozen=True)
class MeshPart:
    """A triangle mesh in file coordinates with one material; ``uv`` is per vertex or None."""

    vertices: np.ndarray
    faces: np.ndarray
    uv: np.ndarray | None
    material: MeshMaterial


@dataclass(frozen=True)
class LoadedFile:
    """The parts of a file and what we noticed while reading it."""

    path: Path
    format: str
    parts: list[MeshPart]
    warnings: list[str] = field(default_factory=list)

    @property
    def face_count(self) -> int:
        return sum(len(p.faces) for p in self.parts)

    @property
    def vertex_count(self) -> int:
        return sum(len(p.vertices) for p in self.parts)


def load_file(path: Path, max_faces: int = 2_000_000) -> LoadedFile:
    """Load ``path`` as a list of parts; raise FormatError for anything unusable."""
    path = Path(path)
    where = str(path)
    fmt = FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise FormatError(
            f"unsupported mesh format {path.suffix or '(no extension)'!r}",
            where=where,
            fix=f"use one of {', '.join(sorted(FORMATS))}",
        )
    if not path.is_file():
        raise FormatError("file not found", where=where, fix="check the path")
    try:
        size = path.stat().st_size
    except OSError as err:
        raise FormatError(f"cannot read the file: {err.strerror}", where=where) from None
    if size == 0:
        raise FormatError("the file is empty", where=where)
    scene = _read_scene(path, fmt)
    warnings: list[str] = []
    parts = []
    pngs: dict[int, bytes] = {}  # one encoding per image object shared by several parts
    for geometry in _geometries(scene, where):
        part = _part(geometry, warnings, pngs)
        if part is not None:
            parts.append(part)
    if not parts:
        raise FormatError("the file holds no triangles", where=where, fix="export a mesh")
    for part in parts:
        if not np.isfinite(part.vertices).all():
            raise FormatError("the mesh has NaN or infinite vertex coordinates", where=where)
    loaded = LoadedFile(path=path, format=fmt, parts=parts, warnings=warnings)
    if loaded.face_count > max_faces:
        raise FormatError(
            f"the mesh has {loaded.face_count} faces, more than the limit of {max_faces}",
            where=where,
            fix="decimate it first or raise max_faces",
        )
    return loaded


def _read_scene(path: Path, fmt: str):
    import trimesh

    try:
        with np.errstate(all="ignore"):
            return trimesh.load(str(path), file_type=fmt, force="scene", process=False)
    except FormatError:
        raise
    except Exception as err:  # third-party parsers raise anything on bad bytes
        what = " ".join(str(err).split())[:200] or type(err).__name__
        raise FormatError(f"cannot parse the {fmt} file: {what}", where=str(path)) from err


def _geometries(scene, where: str) -> list:
    import trimesh

    try:
        items = scene.dump(concatenate=False) if hasattr(scene, "dump") else [scene]
    except Exception as err:  # broken scene graphs fail deep inside trimesh
        what = " ".join(str(err).split())[:200] or type(err).__name__
        raise FormatError(f"cannot flatten the scene graph: {what}", where=where) from err
    return [g for g in items if isinstance(g, trimesh.Trimesh) and len(g.faces) > 0]


def _part(geometry, warnings: list[str], pngs: dict[int, bytes]) -> MeshPart | None:
    vertices = np.asarray(geometry.vertices, dtype=np.float64)
    faces = np.asarray(geometry.faces, dtype=np.int64)
    if faces.ndim != 2 or faces.shape[1] != 3 or len(vertices) == 0:
        return None
    if faces.min() < 0 or faces.max() >= len(vertices):
        warnings.append("dropped a part whose faces index missing vertices")
        return None
    material, uv = _material(geometry, len(vertices), warnings, pngs)
    return MeshPart(vertices=vertices, faces=faces, uv=uv, material=material)


def _material(
    geometry, n_vertices: int, warnings: list[str], pngs: dict[int, bytes]
) -> tuple[MeshMaterial, np.ndarray | None]:
    """Base colour, texture and UVs of a trimesh geometry's visual."""
    visual = geometry.visual
    kind = getattr(visual, "kind", None)
    if kind == "texture":
        mat = getattr(visual, "material", None)
        name = str(getattr(mat, "name", "") or "")
        image = getattr(mat, "baseColorTexture", None)
        if image is None:
            image = getattr(mat, "image", None)
        factor = getattr(mat, "baseColorFactor", None)
        if factor is not None:
            rgba = _rgba(factor)
            if getattr(mat, "alphaMode", None) not in ("BLEND",):
                rgba = (*rgba[:3], 1.0)
        elif image is not None:
            rgba = (1.0, 1.0, 1.0, 1.0)  # OBJ: map_Kd shows the texture as it is
        else:
            rgba = _rgba(getattr(mat, "main_color", (178, 178, 178, 255)))
        uv = getattr(visual, "uv", None)
        if image is not None and (uv is None or len(uv) != n_vertices):
            warnings.append(f"material {name!r}: texture dropped (no per-vertex UVs)")
            image = None
        if image is None:
            return MeshMaterial(rgba=rgba, name=name), None
        uv = np.asarray(uv, dtype=np.float64)
        if not np.isfinite(uv).all():
            warnings.append(f"material {name!r}: texture dropped (non-finite UVs)")
            return MeshMaterial(rgba=rgba, name=name), None
        if id(image) not in pngs:
            pngs[id(image)] = _png(image)
        return MeshMaterial(rgba=rgba, texture_png=pngs[id(image)], name=name), uv
    if kind in ("face", "vertex"):
        colors = visual.face_colors if kind == "face" else visual.vertex_colors
        values, counts = np.unique(np.asarray(colors), axis=0, return_counts=True)
        if len(values) > 1:
            warnings.append(f"{len(values)} per-{kind} colours reduced to the most common one")
        return MeshMaterial(rgba=_rgba(values[int(np.argmax(counts))])), None
    return MeshMaterial(rgba=(0.7, 0.7, 0.7, 1.0)), None


def _rgba(color) -> tuple[float, float, float, float]:
    values = np.asarray(color, dtype=np.float64).ravel()
    if values.size == 3:
        values = np.append(values, 255.0 if values.max() > 1.0 else 1.0)
    if values.size != 4 or not np.isfinite(values).all():
        return (0.7, 0.7, 0.7, 1.0)
    if np.asarray(color).dtype.kind in "iu" or values.max() > 1.0:
        values = values / 255.0
    values = np.clip(values, 0.0, 1.0)
    r, g, b, a = (round(float(v), 4) for v in values)
    return (r, g, b, a)


def _png(image) -> bytes:
    """An RGB PNG of a PIL image, at most MAX_TEXTURE_PX on a side (deterministic bytes)."""
    from PIL import Image

    image = image.convert("RGB")
    if max(image.size) > MAX_TEXTURE_PX:
        ratio = MAX_TEXTURE_PX / max(image.size)
        new = (max(1, round(image.size[0] * ratio)), max(1, round(image.size[1] * ratio)))
        image = image.resize(new, Image.Resampling.LANCZOS)
    buffer = io.BytesIO()
    image.save(buffer, format="PNG", compress_level=6)
    return buffer.getvalue()
