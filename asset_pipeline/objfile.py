"""Byte-deterministic Wavefront OBJ text for visual meshes (with ``vt``) and convex hulls."""

from __future__ import annotations

import numpy as np

POSITION_DECIMALS = 6
UV_DECIMALS = 6


def _fmt(values: np.ndarray, decimals: int) -> list[str]:
    """Fixed-point text of a 2-D array, row by row, never ``-0.000000``."""
    rounded = np.round(np.asarray(values, dtype=np.float64), decimals) + 0.0
    spec = f"{{:.{decimals}f}}"
    return [" ".join(spec.format(v) for v in row) for row in rounded.tolist()]


def obj_bytes(
    vertices: np.ndarray, faces: np.ndarray, uv: np.ndarray | None = None, comment: str = ""
) -> bytes:
    """OBJ text: ``v`` lines, ``vt`` lines (same indexing as ``v``) and 1-based faces."""
    lines = [f"# {line}" for line in comment.splitlines()]
    lines += ["v " + text for text in _fmt(vertices, POSITION_DECIMALS)]
    one_based = (np.asarray(faces, dtype=np.int64) + 1).tolist()
    if uv is not None:
        lines += ["vt " + text for text in _fmt(uv, UV_DECIMALS)]
        lines += [f"f {a}/{a} {b}/{b} {c}/{c}" for a, b, c in one_based]
    else:
        lines += [f"f {a} {b} {c}" for a, b, c in one_based]
    return ("\n".join(lines) + "\n").encode("ascii")


def rounded(vertices: np.ndarray) -> np.ndarray:
    """Vertices as :func:`obj_bytes` writes them (so volumes match the file)."""
    return np.round(np.asarray(vertices, dtype=np.float64), POSITION_DECIMALS) + 0.0
