"""A minimal, byte-deterministic Wavefront OBJ writer (``v x y z`` and ``f a b c`` lines)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from asset_pipeline.procedural.parts import Mesh

DECIMALS = 5


def format_float(value: float, decimals: int = DECIMALS) -> str:
    """Fixed-point text for ``value``, never ``-0.00000``."""
    text = f"{value:.{decimals}f}"
    if text.startswith("-") and float(text) == 0.0:
        text = text[1:]
    return text


def merge_meshes(meshes: Sequence[Mesh]) -> Mesh:
    """One mesh holding all triangles of ``meshes`` (vertices are not shared between them)."""
    vertices, faces, offset = [], [], 0
    for mesh in meshes:
        vertices.append(mesh.vertices)
        faces.append(mesh.faces + offset)
        offset += len(mesh.vertices)
    return Mesh(np.concatenate(vertices), np.concatenate(faces))


def rounded(mesh: Mesh, decimals: int = DECIMALS) -> Mesh:
    """The mesh with its vertices rounded as :func:`obj_bytes` writes them."""
    return Mesh(np.round(mesh.vertices, decimals) + 0.0, mesh.faces)


def obj_bytes(mesh: Mesh, comment: str = "") -> bytes:
    """OBJ text of ``mesh``: an optional comment line, then vertices and 1-based faces."""
    lines = [f"# {line}" for line in comment.splitlines()]
    for x, y, z in mesh.vertices:
        lines.append(f"v {format_float(x)} {format_float(y)} {format_float(z)}")
    for a, b, c in mesh.faces:
        lines.append(f"f {a + 1} {b + 1} {c + 1}")
    return ("\n".join(lines) + "\n").encode("ascii")
