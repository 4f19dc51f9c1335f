"""Repair normalised parts: weld, drop degenerate and duplicate faces, make winding consistent.

Two meshes come out:

* **visual meshes**, one per material (parts sharing a material are merged, since MuJoCo takes
  one material per mesh), keeping UV seams (vertices are merged only when position *and* UV
  agree);
* one **physics mesh**: all parts welded by position (1 µm grid), duplicate faces removed.
  Its watertightness picks CoACD's preprocessing and the deviation reference.

Winding is made consistent across shared edges (a breadth-first walk over face adjacency),
and closed bodies with negative volume are turned inside out; the same flips are applied to
the visual faces, so both meshes agree.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import trimesh
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import breadth_first_order, connected_components

from asset_pipeline.load import MeshMaterial, MeshPart

WELD_M = 1e-6
MIN_FACE_AREA_M2 = 1e-14


@dataclass(frozen=True)
class VisualMesh:
    """One visual mesh with one material; ``uv`` is per vertex when the material is textured."""

    vertices: np.ndarray
    faces: np.ndarray
    uv: np.ndarray | None
    material: MeshMaterial


@dataclass(frozen=True)
class Repaired:
    visuals: list[VisualMesh]
    physics: trimesh.Trimesh
    watertight: bool
    winding_consistent: bool
    stats: dict = field(default_factory=dict)


def repair(parts: list[MeshPart]) -> Repaired:
    """Weld, clean and orient ``parts`` (already in the asset frame)."""
    groups: dict[tuple, list[MeshPart]] = {}
    for part in parts:
        groups.setdefault(part.material.key, []).append(part)
    group_list = list(groups.values())
    all_v, all_f, all_g, all_uv = _stacked(group_list)

    grid = np.round(all_v / WELD_M).astype(np.int64)
    _, first, weld = np.unique(grid, axis=0, return_index=True, return_inverse=True)
    weld = weld.ravel()
    welded_v = all_v[first]
    pf = weld[all_f]
    tri = welded_v[pf]
    area = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1) / 2
    repeated = (pf[:, 0] == pf[:, 1]) | (pf[:, 1] == pf[:, 2]) | (pf[:, 0] == pf[:, 2])
    keep = ~repeated & (area > MIN_FACE_AREA_M2)
    kept_idx = np.flatnonzero(keep)
    _, uniq_first, uniq_inv = np.unique(
        np.sort(pf[kept_idx], axis=1), axis=0, return_index=True, return_inverse=True
    )
    uniq_inv = uniq_inv.ravel()
    order = np.argsort(uniq_first)  # physics faces in source order
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    phys_faces = pf[kept_idx[uniq_first[order]]].copy()

    flip, flipped, inverted = _orient(welded_v, phys_faces)
    phys_faces[flip] = phys_faces[flip][:, ::-1]
    face_flip = np.zeros(len(all_f), dtype=bool)
    face_flip[kept_idx] = flip[rank[uniq_inv]]

    used, phys_local = np.unique(phys_faces, return_inverse=True)
    physics = trimesh.Trimesh(
        vertices=welded_v[used], faces=phys_local.reshape(-1, 3), process=False
    )
    vis_faces = all_f.copy()
    vis_faces[face_flip] = vis_faces[face_flip][:, ::-1]
    visuals = []
    for g, members in enumerate(group_list):
        sel = keep & (all_g == g)
        if not sel.any():
            continue
        textured = members[0].material.texture_png is not None
        visuals.append(_visual(all_v, all_uv if textured else None, vis_faces[sel], members[0]))
    stats = {
        "input_vertices": len(all_v),
        "input_faces": len(all_f),
        "welded_vertices": len(all_v) - len(welded_v),
        "degenerate_faces_removed": int((~keep).sum()),
        "duplicate_faces_removed": int(len(kept_idx) - len(phys_faces)),
        "faces_flipped": flipped,
        "bodies_inverted": inverted,
        "materials": len(visuals),
        "bodies": int(physics.body_count) if len(physics.faces) else 0,
    }
    return Repaired(
        visuals=visuals,
        physics=physics,
        watertight=bool(physics.is_watertight),
        winding_consistent=bool(physics.is_winding_consistent),
        stats=stats,
    )


def _stacked(
    group_list: list[list[MeshPart]],
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """All parts' vertices, faces (indices into them), each face's material group and each
    vertex's texture coordinates (zeros where its material is untextured) in one array each."""
    vertices: list[np.ndarray] = []
    faces: list[np.ndarray] = []
    face_group: list[np.ndarray] = []
    uv: list[np.ndarray] = []
    offset = 0
    for g, members in enumerate(group_list):
        textured = members[0].material.texture_png is not None
        for part in members:
            vertices.append(part.vertices)
            faces.append(part.faces + offset)
            face_group.append(np.full(len(part.faces), g))
            if textured and part.uv is not None:
                uv.append(part.uv)
            else:
                uv.append(np.zeros((len(part.vertices), 2)))
            offset += len(part.vertices)
    return (
        np.concatenate(vertices),
        np.concatenate(faces),
        np.concatenate(face_group),
        np.concatenate(uv),
    )


def _visual(
    vertices: np.ndarray, uv: np.ndarray | None, faces: np.ndarray, part: MeshPart
) -> VisualMesh:
    """Compact one material's faces, merging vertices equal in position (and UV)."""
    used = np.unique(faces)
    key = np.round(vertices[used] / WELD_M).astype(np.int64)
    if uv is not None:
        key = np.hstack([key, np.round(uv[used] / 1e-6).astype(np.int64)])
    _, first, inv = np.unique(key, axis=0, return_index=True, return_inverse=True)
    lookup = np.zeros(len(vertices), dtype=np.int64)
    lookup[used] = inv.ravel()
    src = used[first]
    return VisualMesh(
        vertices=vertices[src],
        faces=lookup[faces],
        uv=None if uv is None else uv[src],
        material=part.material,
    )


def _orient(vertices: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, int, int]:
    """Flip mask making winding consistent and closed bodies outward; (mask, flips, bodies)."""
    n = len(faces)
    flip = np.zeros(n, dtype=bool)
    if n == 0:
        return flip, 0, 0
    directed = np.stack([faces, np.roll(faces, -1, axis=1)], axis=2).reshape(-1, 2)
    owner = np.repeat(np.arange(n), 3)
    undirected = np.sort(directed, axis=1)
    _, edge_id, counts = np.unique(undirected, axis=0, return_inverse=True, return_counts=True)
    edge_id = edge_id.ravel()
    order = np.argsort(edge_id, kind="stable")
    pairs_sorted = edge_id[order]
    starts = np.flatnonzero(np.r_[True, pairs_sorted[1:] != pairs_sorted[:-1]])
    manifold = counts[pairs_sorted[starts]] == 2
    a = order[starts[manifold]]
    b = order[starts[manifold] + 1]
    fa, fb = owner[a], owner[b]
    same_direction = directed[a, 0] == directed[b, 0]
    graph = coo_matrix((np.ones(len(fa)), (fa, fb)), shape=(n, n)).tocsr()
    graph = graph + graph.T
    n_comp, labels = connected_components(graph, directed=False)
    flipped = 0
    if same_direction.any():
        relation: dict[tuple[int, int], bool] = {}
        for x, y, s in zip(fa.tolist(), fb.tolist(), same_direction.tolist()):
            relation[(x, y)] = relation[(y, x)] = s
        for comp in range(n_comp):
            root = int(np.flatnonzero(labels == comp)[0])
            visit, pred = breadth_first_order(graph, root, directed=False)
            for node in visit[1:].tolist():
                parent = int(pred[node])
                flip[node] = flip[parent] ^ relation[(parent, node)]
        flipped = int(flip.sum())
    # Turn closed bodies with negative volume inside out.
    oriented = np.where(flip[:, None], faces[:, ::-1], faces)
    tri = vertices[oriented]
    signed = np.einsum("ij,ij->i", tri[:, 0], np.cross(tri[:, 1], tri[:, 2])) / 6.0
    volume = np.bincount(labels, weights=signed, minlength=n_comp)
    open_edge = counts[edge_id] != 2
    open_comp = np.zeros(n_comp, dtype=bool)
    open_comp[np.unique(labels[owner[open_edge]])] = True
    invert = (~open_comp) & (volume < 0)
    flip ^= invert[labels]
    return flip, flipped, int(invert.sum())
