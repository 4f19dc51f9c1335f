"""Convex decomposition with CoACD in a child process, with a timeout and a fallback chain.

CoACD runs in ``python -m asset_pipeline.decompose IN.npz OUT.npz`` (arrays and parameters in a
temporary ``.npz``), so a hang or a crash of the native code never takes the importer down; on
timeout the child is killed.

Shortcut first: the mesh is split into bodies (connected by shared vertices); a body that is
already convex (every vertex and face centroid within 1 mm of its convex hull's boundary; a
table's legs and top, a shelf's boards) becomes one hull as it is, when there are at most
:data:`MAX_BODY_HULLS` such bodies. Only the remaining bodies go to CoACD. The chain, each step
tried only when the one before failed:

1. ``coacd``: the caller's :class:`CoacdParams`, within ``timeout_s``;
2. ``coacd_coarse``: :meth:`CoacdParams.coarse` (threshold at least 0.1, resolution <= 1000,
   preprocess resolution <= 30, MCTS 10 nodes x 50 iterations, depth <= 2, <= 8 hulls), within
   ``timeout_s`` again; skipped when the settings are already that coarse;
3. ``convex_hull``: the single convex hull of the mesh, computed in process (always works).

Preprocessing follows the mesh: ``off`` for watertight meshes with consistent winding (CoACD
may then cut the mesh as it is), ``on`` (manifold remeshing) otherwise.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path

import numpy as np
import trimesh


@dataclass(frozen=True)
class CoacdParams:
    """CoACD settings (see the CoACD README; defaults are CoACD's, with a hull cap).

    threshold: concavity threshold (0.01-1); lower gives more, finer hulls.
    max_convex_hull: most hulls after merging; -1 for no limit.
    preprocess_resolution: voxel resolution of the manifold preprocessing (20-100).
    resolution: samples per cut evaluation (1000-10000); lower is faster and coarser.
    mcts_nodes: children per node of the Monte Carlo tree search over cut planes.
    mcts_iterations: search iterations per cut (60-2000).
    mcts_max_depth: search depth (2-7).
    timeout_s: wall-clock limit of one CoACD run, seconds (the child is killed after it).
    seed: random seed (fixed for reproducible hulls).
    """

    threshold: float = 0.05
    max_convex_hull: int = 16
    preprocess_resolution: int = 50
    resolution: int = 2000
    mcts_nodes: int = 20
    mcts_iterations: int = 150
    mcts_max_depth: int = 3
    timeout_s: float = 120.0
    seed: int = 0

    def coarse(self) -> CoacdParams:
        """The cheaper settings of the second attempt."""
        return replace(
            self,
            threshold=min(1.0, max(self.threshold, 0.1)),
            max_convex_hull=8 if self.max_convex_hull <= 0 else min(self.max_convex_hull, 8),
            preprocess_resolution=min(self.preprocess_resolution, 30),
            resolution=min(self.resolution, 1000),
            mcts_nodes=min(self.mcts_nodes, 10),
            mcts_iterations=min(self.mcts_iterations, 50),
            mcts_max_depth=min(self.mcts_max_depth, 2),
        )

    def run_kwargs(self, preprocess_mode: str) -> dict:
        """Keyword arguments of ``coacd.run_coacd``."""
        kwargs = asdict(self)
        kwargs.pop("timeout_s")
        kwargs["preprocess_mode"] = preprocess_mode
        return kwargs


@dataclass(frozen=True)
class Decomposition:
    """Hull vertex sets (asset frame), the method that made them and every attempt."""

    hulls: list[np.ndarray]
    method: str
    preprocess_mode: str
    attempts: list[dict] = field(default_factory=list)


MAX_BODY_HULLS = 32
CONVEX_TOL_M = 0.001


def decompose(mesh: trimesh.Trimesh, params: CoacdParams, manifold: bool) -> Decomposition:
    """Convex bodies as they are, the rest through the CoACD fallback chain."""
    convex, rest = [], []
    for faces in _bodies(mesh):
        points = np.asarray(mesh.vertices)[np.unique(mesh.faces[faces])]
        centroids = np.asarray(mesh.triangles_center)[faces]
        (convex if _is_convex(points, centroids) else rest).append(faces)
    if len(convex) > MAX_BODY_HULLS:
        convex, rest = [], [np.arange(len(mesh.faces))]
    hulls = [np.asarray(mesh.vertices)[np.unique(mesh.faces[f])] for f in convex]
    if not rest:
        attempt = {"method": "convex_bodies", "status": "ok", "bodies": len(convex)}
        return Decomposition(hulls, "convex_bodies", "none", [attempt])
    if convex:
        faces = np.concatenate(rest)
        used, local = np.unique(mesh.faces[faces], return_inverse=True)
        sub = trimesh.Trimesh(mesh.vertices[used], local.reshape(-1, 3), process=False)
        manifold = bool(sub.is_watertight and sub.is_winding_consistent)
        result = _chain(sub, params, manifold)
        attempt = {"method": "convex_bodies", "status": "ok", "bodies": len(convex)}
        return Decomposition(
            hulls + result.hulls,
            f"convex_bodies+{result.method}",
            result.preprocess_mode,
            [attempt, *result.attempts],
        )
    return _chain(mesh, params, manifold)


def _bodies(mesh: trimesh.Trimesh) -> list[np.ndarray]:
    """Face indices of each body (faces connected through shared vertices)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    faces = np.asarray(mesh.faces)
    n = len(mesh.vertices)
    rows = np.concatenate([faces[:, 0], faces[:, 1]])
    cols = np.concatenate([faces[:, 1], faces[:, 2]])
    graph = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(n, n))
    _, labels = connected_components(graph, directed=False)
    face_label = labels[faces[:, 0]]
    order = np.argsort(face_label, kind="stable")
    splits = np.flatnonzero(np.diff(face_label[order])) + 1
    return np.split(order, splits)


def _is_convex(points: np.ndarray, centroids: np.ndarray) -> bool:
    from scipy.spatial import ConvexHull, QhullError

    try:
        equations = ConvexHull(points).equations
    except (QhullError, ValueError):
        return True  # flat: one (sliver) hull, made a box later
    depth = np.vstack([points, centroids]) @ equations[:, :3].T + equations[:, 3]
    return bool((depth.max(axis=1) >= -CONVEX_TOL_M).all())


def _chain(mesh: trimesh.Trimesh, params: CoacdParams, manifold: bool) -> Decomposition:
    """Run the fallback chain on ``mesh``; ``manifold`` picks CoACD's preprocessing."""
    mode = "off" if manifold else "on"
    attempts: list[dict] = []
    tries = [("coacd", params)]
    coarse = params.coarse()
    if coarse != params:
        tries.append(("coacd_coarse", coarse))
    else:
        attempts.append(
            {"method": "coacd_coarse", "status": "skipped", "reason": "settings already coarse"}
        )
    for method, settings in tries:
        start = time.perf_counter()
        hulls, status, reason = _run_child(mesh, settings, mode)
        record = {
            "method": method,
            "status": status,
            "seconds": round(time.perf_counter() - start, 3),
            "params": settings.run_kwargs(mode) | {"timeout_s": settings.timeout_s},
        }
        if reason:
            record["reason"] = reason
        attempts.append(record)
        if status == "ok":
            return Decomposition(
                hulls=hulls, method=method, preprocess_mode=mode, attempts=attempts
            )
    start = time.perf_counter()
    hull = np.asarray(mesh.vertices, dtype=np.float64)  # hulls.py takes the hull (or a box)
    attempts.append(
        {"method": "convex_hull", "status": "ok", "seconds": round(time.perf_counter() - start, 3)}
    )
    return Decomposition(
        hulls=[hull], method="convex_hull", preprocess_mode=mode, attempts=attempts
    )


def _run_child(
    mesh: trimesh.Trimesh, params: CoacdParams, mode: str
) -> tuple[list[np.ndarray], str, str]:
    """(hulls, status, reason): status is ok, timeout or error."""
    with tempfile.TemporaryDirectory(prefix="holomj_coacd_") as tmp:
        src, dst = Path(tmp) / "in.npz", Path(tmp) / "out.npz"
        np.savez(
            src,
            vertices=np.asarray(mesh.vertices, dtype=np.float64),
            faces=np.asarray(mesh.faces, dtype=np.int32),
            params=np.array(json.dumps(params.run_kwargs(mode))),
        )
        command = [sys.executable, "-m", "asset_pipeline.decompose", str(src), str(dst)]
        try:
            proc = subprocess.run(
                command, capture_output=True, timeout=max(params.timeout_s, 0.001)
            )
        except subprocess.TimeoutExpired:
            return [], "timeout", f"CoACD did not finish within {params.timeout_s:g} s (killed)"
        if proc.returncode != 0 or not dst.is_file():
            tail = proc.stderr.decode("utf-8", "replace").strip().splitlines()[-1:]
            detail = f": {tail[0][:200]}" if tail else ""
            return [], "error", f"CoACD exited with code {proc.returncode}{detail}"
        with np.load(dst) as data:
            hulls = [data[f"hull_{i}"] for i in range(int(data["count"]))]
    hulls = [h for h in hulls if len(h) >= 4]
    if not hulls:
        return [], "error", "CoACD returned no usable hull"
    return hulls, "ok", ""


def _child(src: str, dst: str) -> None:
    """Child process: read the mesh, run CoACD, write the hull vertices."""
    import coacd

    coacd.set_log_level("error")
    with np.load(src) as data:
        vertices, faces = data["vertices"], data["faces"]
        kwargs = json.loads(str(data["params"]))
    parts = coacd.run_coacd(coacd.Mesh(vertices, faces), **kwargs)
    arrays = {f"hull_{i}": np.asarray(v, dtype=np.float64) for i, (v, _) in enumerate(parts)}
    tmp = dst + ".part.npz"
    np.savez(tmp, count=np.array(len(parts)), **arrays)
    os.replace(tmp, dst)


if __name__ == "__main__":
    _child(sys.argv[1], sys.argv[2])
