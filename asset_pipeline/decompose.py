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
2. ``coacd_coarse``: :meth:`CoacdParams.coarse` (threshold at least 0.2, resolution <= 500,
   preprocess resolution <= 20, MCTS 6 nodes x 15 iterations, depth <= 2, <= 8 hulls), within
   ``timeout_s`` again; skipped when the settings are already that coarse;
3. ``convex_hull``: the single convex hull of the mesh, computed in process (always works).

Preprocessing follows the mesh: ``off`` for watertight meshes with consistent winding (CoACD
may then cut the mesh as it is), ``on`` (manifold remeshing) otherwise.

A result of step 2 or 3 is *degraded*: :attr:`Decomposition.degraded_reason` says why in one
line (``"CoACD timed out after 60 s; single convex hull"``), so callers can warn about it and
keep it out of caches (a timeout on a busy machine must not become permanent).
"""

from __future__ import annotations

import json
import os
import resource
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
    """CoACD settings (see the CoACD README); the defaults are the ``default`` preset.

    threshold: concavity threshold (0.01-1); lower gives more, finer hulls.
    preprocessed_threshold: the threshold for meshes CoACD must first remesh (not watertight:
        scans, open surfaces); None for ``threshold``. The remesh is only as fine as its voxel
        grid (1/25 of the size at resolution 25), so a finer threshold there buys time, not
        detail.
    max_convex_hull: most hulls after merging; -1 for no limit.
    preprocess_resolution: voxel resolution of the manifold preprocessing (20-100); the
        remeshed surface CoACD then cuts grows with its square (48k triangles at 40 for a
        soup can), and so does the time.
    resolution: samples per cut evaluation (1000-10000); lower is faster and coarser.
    mcts_nodes: children per node of the Monte Carlo tree search over cut planes.
    mcts_iterations: search iterations per cut (60-2000).
    mcts_max_depth: search depth (2-7).
    timeout_s: wall-clock limit of one CoACD run, seconds (the child is killed after it).
    seed: random seed (fixed for reproducible hulls).

    The defaults trade CoACD's own search (preprocessing at 50, 2000 samples, 20 nodes x 150
    iterations x depth 3: a minute or more of CPU per scanned mesh) for a shallower, narrower
    search on a coarser preprocessing grid, keeping CoACD's threshold (0.05) for watertight
    meshes, whose thin walls (boxes, bowls, plates) need it; see ``scripts/bench_assets.py``
    for the measured time and hull volume ratios. The ``fine`` preset of
    :mod:`asset_pipeline.manage` keeps CoACD's search settings.
    """

    threshold: float = 0.05
    preprocessed_threshold: float | None = 0.1
    max_convex_hull: int = 16
    preprocess_resolution: int = 25
    resolution: int = 800
    mcts_nodes: int = 8
    mcts_iterations: int = 25
    mcts_max_depth: int = 2
    timeout_s: float = 120.0
    seed: int = 0

    def coarse(self) -> CoacdParams:
        """The cheaper settings of the second attempt (a run that timed out gets a search
        several times cheaper)."""
        coarse_threshold = min(1.0, max(self.threshold, 0.2))
        return replace(
            self,
            threshold=coarse_threshold,
            preprocessed_threshold=(
                None
                if self.preprocessed_threshold is None
                else max(self.preprocessed_threshold, coarse_threshold)
            ),
            max_convex_hull=8 if self.max_convex_hull <= 0 else min(self.max_convex_hull, 8),
            preprocess_resolution=min(self.preprocess_resolution, 20),
            resolution=min(self.resolution, 500),
            mcts_nodes=min(self.mcts_nodes, 6),
            mcts_iterations=min(self.mcts_iterations, 15),
            mcts_max_depth=min(self.mcts_max_depth, 2),
        )

    def threshold_for(self, preprocess_mode: str) -> float:
        """The concavity threshold used with ``preprocess_mode`` ("on": remeshed first)."""
        if preprocess_mode == "on" and self.preprocessed_threshold is not None:
            return self.preprocessed_threshold
        return self.threshold

    def run_kwargs(self, preprocess_mode: str) -> dict:
        """Keyword arguments of ``coacd.run_coacd``."""
        kwargs = asdict(self)
        kwargs.pop("timeout_s")
        kwargs.pop("preprocessed_threshold")
        kwargs["threshold"] = self.threshold_for(preprocess_mode)
        kwargs["preprocess_mode"] = preprocess_mode
        return kwargs


@dataclass(frozen=True)
class Decomposition:
    """Hull vertex sets (asset frame), the method that made them and every attempt.

    ``degraded_reason`` is None when CoACD ran as asked (or was not needed), else one line
    saying how it failed and what was used instead.
    """

    hulls: list[np.ndarray]
    method: str
    preprocess_mode: str
    attempts: list[dict] = field(default_factory=list)
    degraded_reason: str | None = None

    @property
    def degraded(self) -> bool:
        """True when a fallback (coarser settings, single convex hull) replaced CoACD's result."""
        return self.degraded_reason is not None


MAX_BODY_HULLS = 32
CONVEX_TOL_M = 0.001


def decompose(mesh: trimesh.Trimesh, params: CoacdParams, manifold: bool) -> Decomposition:
    """Convex bodies as they are, the rest through the CoACD fallback chain."""
    convex: list[np.ndarray] = []
    rest: list[np.ndarray] = []
    for faces in bodies(mesh):
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
        reason = result.degraded_reason
        return Decomposition(
            hulls + result.hulls,
            f"convex_bodies+{result.method}",
            result.preprocess_mode,
            [attempt, *result.attempts],
            f"{reason} for the non-convex bodies" if reason else None,
        )
    return _chain(mesh, params, manifold)


def bodies(mesh: trimesh.Trimesh) -> list[np.ndarray]:
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
        cpu_start = _children_cpu_seconds()
        hulls, status, reason = _run_child(mesh, settings, mode)
        record = {
            "method": method,
            "status": status,
            "seconds": round(time.perf_counter() - start, 3),
            # CPU time of the child (all its threads): unlike wall time, not inflated by
            # other work on a busy machine.
            "cpu_seconds": round(_children_cpu_seconds() - cpu_start, 3),
            "params": settings.run_kwargs(mode) | {"timeout_s": settings.timeout_s},
        }
        if reason:
            record["reason"] = reason
        attempts.append(record)
        if status == "ok":
            return Decomposition(
                hulls=hulls,
                method=method,
                preprocess_mode=mode,
                attempts=attempts,
                degraded_reason=degraded_reason(attempts, method),
            )
    start = time.perf_counter()
    hull = np.asarray(mesh.vertices, dtype=np.float64)  # hulls.py takes the hull (or a box)
    attempts.append(
        {"method": "convex_hull", "status": "ok", "seconds": round(time.perf_counter() - start, 3)}
    )
    return Decomposition(
        hulls=[hull],
        method="convex_hull",
        preprocess_mode=mode,
        attempts=attempts,
        degraded_reason=degraded_reason(attempts, "convex_hull"),
    )


FALLBACK_NAMES = {"coacd_coarse": "coarser CoACD settings", "convex_hull": "single convex hull"}


def degraded_reason(attempts: list[dict], method: str) -> str | None:
    """One line on why ``method`` replaced CoACD's result, or None if it did not.

    Each distinct failure of the CoACD attempts, then what was used instead:
    ``"CoACD timed out after 60 s; single convex hull"``.
    """
    if method not in FALLBACK_NAMES:
        return None
    failures: list[str] = []
    for attempt in attempts:
        phrase = _failure_phrase(attempt)
        if phrase and phrase not in failures:
            failures.append(phrase)
    return "; ".join([*failures, FALLBACK_NAMES[method]])


def _failure_phrase(attempt: dict) -> str | None:
    """How one CoACD attempt failed, in a few words; None for a success or a skipped step."""
    if attempt["status"] == "timeout":
        return f"CoACD timed out after {attempt['params']['timeout_s']:g} s"
    if attempt["status"] == "error":
        return attempt.get("reason") or "CoACD failed"
    return None


def _children_cpu_seconds() -> float:
    """User + system CPU seconds of this process's finished (waited-for) child processes."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


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
            return [], "error", _child_error(proc.returncode, proc.stderr)
        with np.load(dst) as data:
            hulls = [data[f"hull_{i}"] for i in range(int(data["count"]))]
    hulls = [h for h in hulls if len(h) >= 4]
    if not hulls:
        return [], "error", "CoACD returned no usable hull"
    return hulls, "ok", ""


def _child_error(returncode: int, stderr: bytes) -> str:
    """The reason of a failed child: CoACD missing (it could not be imported) or crashed."""
    tail = stderr.decode("utf-8", "replace").strip().splitlines()[-1:]
    last = tail[0][:200] if tail else ""
    if last.startswith(("ModuleNotFoundError", "ImportError")):
        return f"CoACD unavailable ({last})"
    detail = f": {last}" if last else ""
    return f"CoACD exited with code {returncode}{detail}"


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
    np.savez(tmp, count=np.array(len(parts)), **arrays)  # type: ignore[arg-type]  # numpy's stub types **kwds as its allow_pickle flag
    os.replace(tmp, dst)


if __name__ == "__main__":
    _child(sys.argv[1], sys.argv[2])
