"""A minimal, byte-deterministic Wavefront OBJ writer.

Untextured meshes are written as ``v x y z`` and ``f a b c`` lines; textured ones also get
``vt u v`` lines and ``f a/ta b/tb c/tc`` faces (MuJoCo keeps the texture indices apart from the
vertex indices, so a shared vertex keeps one position and smooth shading).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from asset_pipeline.procedural.parts import Mesh

DECIMALS = 5
UV_DECIMALS = 3


def merge_meshes(meshes: Sequence[Mesh]) -> Mesh:
    """One mesh holding all triangles of ``meshes`` (vertices are not shared between them).

    If any mesh carries texture coordinates the result does too; a mesh without them gets one
    coordinate (0, 0) for all its corners.
    """
    vertices, faces, offset = [], [], 0
    for mesh in meshes:
        vertices.append(mesh.vertices)
        faces.append(mesh.faces + offset)
        offset += len(mesh.vertices)
    merged_vertices, merged_faces = np.concatenate(vertices), np.concatenate(faces)
    if all(mesh.uv is None for mesh in meshes):
        return Mesh(merged_vertices, merged_faces)
    uvs, uv_faces, uv_offset = [], [], 0
    for mesh in meshes:
        if mesh.uv is None or mesh.uv_faces is None:
            uv, uv_index = np.zeros((1, 2)), np.zeros_like(mesh.faces)
        else:
            uv, uv_index = mesh.uv, mesh.uv_faces
        uvs.append(uv)
        uv_faces.append(uv_index + uv_offset)
        uv_offset += len(uv)
    return Mesh(merged_vertices, merged_faces, np.concatenate(uvs), np.concatenate(uv_faces))


def rounded(mesh: Mesh, decimals: int = DECIMALS) -> Mesh:
    """The mesh with its vertices (and texture coordinates) rounded as :func:`obj_bytes`
    writes them."""
    uv = None if mesh.uv is None else np.round(mesh.uv, UV_DECIMALS) + 0.0
    return Mesh(np.round(mesh.vertices, decimals) + 0.0, mesh.faces, uv, mesh.uv_faces)


def _rows(prefix: str, values: np.ndarray, decimals: int) -> str:
    """``prefix`` and the fixed-point values of each row, one line per row (no ``-0``)."""
    values = np.round(np.asarray(values, dtype=np.float64), decimals) + 0.0
    if values.size == 0:
        return ""
    line = prefix + "".join(f" %.{decimals}f" for _ in range(values.shape[1])) + "\n"
    return (line * len(values)) % tuple(values.ravel().tolist())


def obj_bytes(mesh: Mesh, comment: str = "") -> bytes:
    """OBJ text of ``mesh``: an optional comment line, vertices, texture coordinates if any,
    then 1-based faces."""
    parts = [f"# {line}\n" for line in comment.splitlines()]
    parts.append(_rows("v", mesh.vertices, DECIMALS))
    faces = (np.asarray(mesh.faces, dtype=np.int64) + 1).ravel().tolist()
    if mesh.uv is None or mesh.uv_faces is None:
        parts.append(("f %d %d %d\n" * len(mesh.faces)) % tuple(faces))
    else:
        parts.append(_rows("vt", mesh.uv, UV_DECIMALS))
        uv_faces = (np.asarray(mesh.uv_faces, dtype=np.int64) + 1).ravel().tolist()
        pairs = [v for pair in zip(faces, uv_faces, strict=True) for v in pair]
        parts.append(("f %d/%d %d/%d %d/%d\n" * len(mesh.faces)) % tuple(pairs))
    return "".join(parts).encode("ascii")
