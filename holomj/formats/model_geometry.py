"""Triangles, materials and poses of a compiled MuJoCo model, for the exporters (GLB, USD, URDF).

Everything is read from the compiled ``MjModel`` (what is simulated): mesh geoms from their
vertices, faces, normals and texture coordinates (MuJoCo keeps separate indices per face corner,
so corners are unwelded and merged again where all three agree), primitives as triangle meshes
(boxes with one texture tile set per face, as MuJoCo maps a 2D texture onto them), materials with
their colour, texture, repeat and shininess. A geom's triangles are in its own frame; the pose
of every body and geom comes from ``mj_kinematics`` at the model's initial state (``qpos0``) or
the joint positions the caller gives.

Which geoms are seen and which collide follows the house style: groups 0 (structure), 1
(ceilings) and 2 (visual meshes) are drawn, a geom with ``contype`` or ``conaffinity`` set takes
part in contacts, and collider-only geoms (groups 3 and up) are drawn only on request.
"""

from __future__ import annotations

import io
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import cached_property

import mujoco
import numpy as np

VISIBLE_GROUPS = (0, 1, 2)
CEILING_GROUP = 1
_RGB_ROLE = int(mujoco.mjtTextureRole.mjTEXROLE_RGB)
_DEFAULT_GEOM_RGBA = (0.5, 0.5, 0.5, 1.0)
_SEGMENTS = 24  # around cylinders, capsules and spheres


@dataclass(frozen=True)
class Triangles:
    """An indexed triangle mesh: float32 positions and normals (n, 3), optional float32 texture
    coordinates (n, 2, glTF's convention: v = 0 is the image's top row) and uint32 faces (m, 3)."""

    positions: np.ndarray
    normals: np.ndarray
    uvs: np.ndarray | None
    faces: np.ndarray

    def transformed(self, rotation: np.ndarray, translation: np.ndarray) -> Triangles:
        """These triangles moved by ``rotation`` (3x3) then ``translation``."""
        rotation = np.asarray(rotation, dtype=float)
        positions = self.positions.astype(float) @ rotation.T + np.asarray(translation)
        normals = self.normals.astype(float) @ rotation.T
        return Triangles(
            positions.astype(np.float32), normals.astype(np.float32), self.uvs, self.faces
        )

    @property
    def empty(self) -> bool:
        return len(self.faces) == 0

    @staticmethod
    def concat(parts: Sequence[Triangles]) -> Triangles:
        """One mesh of ``parts`` (texture coordinates kept when every part has them)."""
        offsets = np.cumsum([0] + [len(p.positions) for p in parts[:-1]])
        with_uv = all(p.uvs is not None for p in parts)
        return Triangles(
            np.vstack([p.positions for p in parts]).astype(np.float32),
            np.vstack([p.normals for p in parts]).astype(np.float32),
            np.vstack([p.uvs for p in parts if p.uvs is not None]).astype(np.float32)
            if with_uv
            else None,
            np.vstack([p.faces + o for p, o in zip(parts, offsets)]).astype(np.uint32),
        )


@dataclass(frozen=True)
class Look:
    """What a geom looks like: its colour as written in the MJCF (display values), its 2D texture
    (a model texture id) with how often it repeats, and MuJoCo's shading numbers."""

    name: str
    rgba: tuple[float, float, float, float]
    texture: int | None
    repeat: tuple[float, float]
    specular: float
    shininess: float
    reflectance: float
    emission: float

    @property
    def roughness(self) -> float:
        return round(min(1.0, max(0.15, 1.0 - 0.8 * self.shininess)), 4)

    @property
    def linear_rgba(self) -> tuple[float, float, float, float]:
        """The colour as glTF and USD want it: linear RGB (sRGB decoded), alpha as is."""
        red, green, blue = (round(srgb_to_linear(c), 6) for c in self.rgba[:3])
        return (red, green, blue, self.rgba[3])


def srgb_to_linear(value: float) -> float:
    """One sRGB channel in [0, 1] as linear light."""
    value = min(1.0, max(0.0, float(value)))
    return value / 12.92 if value <= 0.04045 else ((value + 0.055) / 1.055) ** 2.4


class ModelGeometry:
    """Read-only views of ``model`` posed at ``qpos`` (default: ``qpos0``): geom triangles
    (cached per shape), looks, textures as PNG, and world poses of bodies, geoms and lights."""

    def __init__(self, model: mujoco.MjModel, qpos: np.ndarray | None = None) -> None:
        self.model = model
        self.data = mujoco.MjData(model)
        if qpos is not None:
            self.data.qpos[:] = qpos
        mujoco.mj_kinematics(model, self.data)
        mujoco.mj_comPos(model, self.data)
        mujoco.mj_camlight(model, self.data)  # lights' world poses
        self._shapes: dict[tuple, Triangles | None] = {}
        self._pngs: dict[int, bytes] = {}

    # --- names and membership ---------------------------------------------------------------

    def body_name(self, body: int) -> str:
        return self.model.body(body).name

    def geom_name(self, geom: int) -> str:
        return self.model.geom(geom).name

    def body_geoms(self, body: int) -> range:
        start = int(self.model.body_geomadr[body])
        return range(start, start + int(self.model.body_geomnum[body])) if start >= 0 else range(0)

    @cached_property
    def children(self) -> dict[int, list[int]]:
        """Body id -> ids of its child bodies (world = 0)."""
        out: dict[int, list[int]] = {b: [] for b in range(self.model.nbody)}
        for body in range(1, self.model.nbody):
            out[int(self.model.body_parentid[body])].append(body)
        return out

    def body_joints(self, body: int) -> range:
        start = int(self.model.body_jntadr[body])
        return range(start, start + int(self.model.body_jntnum[body])) if start >= 0 else range(0)

    def is_visible(self, geom: int) -> bool:
        """Drawn in the scene as seen: groups 0-2, not fully transparent, a shape we draw."""
        model = self.model
        return (
            int(model.geom_group[geom]) in VISIBLE_GROUPS
            and self.rgba(geom)[3] > 0.0
            and self._drawable(geom)
        )

    def is_collider(self, geom: int) -> bool:
        """Takes part in contacts (``contype`` or ``conaffinity`` set)."""
        return bool(self.model.geom_contype[geom] or self.model.geom_conaffinity[geom])

    def is_hidden_collider(self, geom: int) -> bool:
        """A collision geom that is not drawn (groups 3 and up; planes excluded)."""
        model = self.model
        return int(model.geom_group[geom]) not in VISIBLE_GROUPS and self._drawable(geom)

    def _drawable(self, geom: int) -> bool:
        kind = int(self.model.geom_type[geom])
        if kind == mujoco.mjtGeom.mjGEOM_PLANE:
            return bool(self.model.geom_size[geom][0] > 0 and self.model.geom_size[geom][1] > 0)
        return kind in (
            mujoco.mjtGeom.mjGEOM_SPHERE,
            mujoco.mjtGeom.mjGEOM_CAPSULE,
            mujoco.mjtGeom.mjGEOM_ELLIPSOID,
            mujoco.mjtGeom.mjGEOM_CYLINDER,
            mujoco.mjtGeom.mjGEOM_BOX,
            mujoco.mjtGeom.mjGEOM_MESH,
        )

    # --- poses ----------------------------------------------------------------------------

    def body_pose(self, body: int) -> tuple[np.ndarray, np.ndarray]:
        """World position (3,) and rotation matrix (3, 3) of ``body``."""
        return self.data.xpos[body].copy(), self.data.xmat[body].reshape(3, 3).copy()

    def geom_pose(self, geom: int) -> tuple[np.ndarray, np.ndarray]:
        """World position and rotation matrix of ``geom``."""
        return self.data.geom_xpos[geom].copy(), self.data.geom_xmat[geom].reshape(3, 3).copy()

    def geom_in_body(self, geom: int) -> tuple[np.ndarray, np.ndarray]:
        """Position and rotation of ``geom`` in its body's frame (at this pose)."""
        body = int(self.model.geom_bodyid[geom])
        bpos, brot = self.body_pose(body)
        gpos, grot = self.geom_pose(geom)
        return brot.T @ (gpos - bpos), brot.T @ grot

    # --- looks ----------------------------------------------------------------------------

    def rgba(self, geom: int) -> tuple[float, float, float, float]:
        model = self.model
        rgba = model.geom_rgba[geom]
        material = int(model.geom_matid[geom])
        if material >= 0 and np.allclose(rgba, _DEFAULT_GEOM_RGBA):
            rgba = model.mat_rgba[material]
        red, green, blue, alpha = (float(v) for v in rgba)
        return (red, green, blue, alpha)

    def look(self, geom: int) -> Look:
        model = self.model
        material = int(model.geom_matid[geom])
        rgba = self.rgba(geom)
        if material < 0:
            return Look(f"rgba/{_rgba_key(rgba)}", rgba, None, (1.0, 1.0), 0.5, 0.5, 0.0, 0.0)
        texture = int(model.mat_texid[material, _RGB_ROLE])
        if texture >= 0 and int(model.tex_type[texture]) != mujoco.mjtTexture.mjTEXTURE_2D:
            texture = -1
        name = model.material(material).name or f"material_{material}"
        if not np.allclose(rgba, model.mat_rgba[material]):
            name = f"{name}/{_rgba_key(rgba)}"
        return Look(
            name,
            rgba,
            texture if texture >= 0 else None,
            (float(model.mat_texrepeat[material][0]), float(model.mat_texrepeat[material][1])),
            float(model.mat_specular[material]),
            float(model.mat_shininess[material]),
            float(model.mat_reflectance[material]),
            float(model.mat_emission[material]),
        )

    def texture_name(self, texture: int) -> str:
        return self.model.texture(texture).name or f"texture_{texture}"

    def texture_png(self, texture: int) -> bytes:
        """A 2D texture of the model as PNG bytes (greyscale when all its channels agree)."""
        if texture not in self._pngs:
            from PIL import Image

            model = self.model
            width, height = int(model.tex_width[texture]), int(model.tex_height[texture])
            channels = int(model.tex_nchannel[texture])
            start = int(model.tex_adr[texture])
            pixels = np.asarray(
                model.tex_data[start : start + width * height * channels], dtype=np.uint8
            ).reshape(height, width, channels)
            if (
                channels >= 3
                and np.array_equal(pixels[..., 0], pixels[..., 1])
                and np.array_equal(pixels[..., 0], pixels[..., 2])
            ) or channels == 1:
                image = Image.fromarray(np.ascontiguousarray(pixels[..., 0]), "L")
            else:
                image = Image.fromarray(pixels[..., :4] if channels == 4 else pixels[..., :3])
            buffer = io.BytesIO()
            image.save(buffer, format="PNG", optimize=True)
            self._pngs[texture] = buffer.getvalue()
        return self._pngs[texture]

    # --- shapes ---------------------------------------------------------------------------

    def triangles(self, geom: int, repeat: tuple[float, float] = (1.0, 1.0)) -> Triangles | None:
        """``geom``'s surface in its own frame (None for shapes we do not draw: hfields,
        SDFs, infinite planes); texture coordinates scaled by ``repeat``."""
        model = self.model
        kind = int(model.geom_type[geom])
        size = tuple(round(float(v), 7) for v in model.geom_size[geom])
        shape = int(model.geom_dataid[geom]) if kind == mujoco.mjtGeom.mjGEOM_MESH else size
        key = (kind, shape, round(repeat[0], 6), round(repeat[1], 6))
        if key not in self._shapes:
            self._shapes[key] = self._make_triangles(geom, kind, repeat)
        return self._shapes[key]

    def _make_triangles(
        self, geom: int, kind: int, repeat: tuple[float, float]
    ) -> Triangles | None:
        size = np.asarray(self.model.geom_size[geom], dtype=float)
        if kind == mujoco.mjtGeom.mjGEOM_MESH:
            mesh = int(self.model.geom_dataid[geom])
            return mesh_triangles(self.model, mesh, repeat) if mesh >= 0 else None
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            return box_triangles(size, repeat)
        if kind == mujoco.mjtGeom.mjGEOM_PLANE:
            if size[0] <= 0 or size[1] <= 0:
                return None
            return box_triangles(np.array([size[0], size[1], 0.0]), repeat, faces=("+z",))
        return _primitive(kind, size, repeat)

    def world_triangles(self, geoms: Iterable[int]) -> Triangles | None:
        """The union of ``geoms`` in the world frame (None when none is drawable)."""
        parts = []
        for geom in geoms:
            tris = self.triangles(geom)
            if tris is not None and not tris.empty:
                pos, rot = self.geom_pose(geom)
                parts.append(tris.transformed(rot, pos))
        return Triangles.concat(parts) if parts else None


def _rgba_key(rgba: Sequence[float]) -> str:
    return "_".join(f"{v:.3g}" for v in rgba)


def mesh_triangles(model: mujoco.MjModel, mesh: int, repeat: tuple[float, float]) -> Triangles:
    """A mesh asset of ``model`` (in its mesh frame) with its normals and texture coordinates."""
    vstart, vcount = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
    fstart, fcount = int(model.mesh_faceadr[mesh]), int(model.mesh_facenum[mesh])
    vertices = np.asarray(model.mesh_vert[vstart : vstart + vcount], dtype=np.float32)
    faces = np.asarray(model.mesh_face[fstart : fstart + fcount], dtype=np.int64)
    corners = [vertices[faces.reshape(-1)]]
    nstart, ncount = int(model.mesh_normaladr[mesh]), int(model.mesh_normalnum[mesh])
    if ncount > 0:
        normals = np.asarray(model.mesh_normal[nstart : nstart + ncount], dtype=np.float32)
        face_normals = np.asarray(model.mesh_facenormal[fstart : fstart + fcount], dtype=np.int64)
        corner_normals = normals[face_normals.reshape(-1)]
    else:
        corner_normals = _flat_normals(corners[0])
    corners.append(corner_normals)
    tstart = int(model.mesh_texcoordadr[mesh])
    has_uv = tstart >= 0 and int(model.mesh_texcoordnum[mesh]) > 0
    if has_uv:
        count = int(model.mesh_texcoordnum[mesh])
        texcoords = np.asarray(model.mesh_texcoord[tstart : tstart + count], dtype=np.float32)
        face_tex = np.asarray(model.mesh_facetexcoord[fstart : fstart + fcount], dtype=np.int64)
        corners.append(texcoords[face_tex.reshape(-1)] * np.asarray(repeat, dtype=np.float32))
    table = np.hstack(corners)
    unique, inverse = np.unique(table, axis=0, return_inverse=True)
    return Triangles(
        np.ascontiguousarray(unique[:, 0:3], dtype=np.float32),
        np.ascontiguousarray(_unit(unique[:, 3:6]), dtype=np.float32),
        np.ascontiguousarray(unique[:, 6:8], dtype=np.float32) if has_uv else None,
        inverse.reshape(-1, 3).astype(np.uint32),
    )


_BOX_FACES = {
    # normal axis, sign, u axis, v axis (v runs down the image: glTF's convention)
    "+x": (0, 1.0, 1, 2),
    "-x": (0, -1.0, 1, 2),
    "+y": (1, 1.0, 0, 2),
    "-y": (1, -1.0, 0, 2),
    "+z": (2, 1.0, 0, 1),
    "-z": (2, -1.0, 0, 1),
}


def box_triangles(
    half: np.ndarray, repeat: tuple[float, float], faces: Sequence[str] = tuple(_BOX_FACES)
) -> Triangles:
    """A box of half-sizes ``half``, four vertices per face, each face's texture coordinates
    spanning ``repeat`` tiles (MuJoCo's mapping of a 2D texture onto a box)."""
    positions: list[np.ndarray] = []
    normals: list[np.ndarray] = []
    uvs: list[tuple[float, float]] = []
    tris: list[tuple[int, int, int]] = []
    for name in faces:
        axis, sign, u_axis, v_axis = _BOX_FACES[name]
        base = len(positions)
        for u, v in ((0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)):
            point = np.zeros(3)
            point[axis] = sign * half[axis]
            point[u_axis] = (2 * u - 1) * half[u_axis]
            point[v_axis] = (1 - 2 * v) * half[v_axis]
            positions.append(point)
            normal = np.zeros(3)
            normal[axis] = sign
            normals.append(normal)
            uvs.append((u * repeat[0], v * repeat[1]))
        first, second = (base, base + 1, base + 2), (base, base + 2, base + 3)
        # counter-clockwise seen from outside
        outward = np.cross(
            positions[base + 1] - positions[base], positions[base + 2] - positions[base]
        )
        if np.dot(outward, normals[base]) < 0:
            first, second = (base, base + 2, base + 1), (base, base + 3, base + 2)
        tris += [first, second]
    return Triangles(
        np.asarray(positions, dtype=np.float32),
        np.asarray(normals, dtype=np.float32),
        np.asarray(uvs, dtype=np.float32),
        np.asarray(tris, dtype=np.uint32),
    )


def _primitive(kind: int, size: np.ndarray, repeat: tuple[float, float]) -> Triangles | None:
    import trimesh

    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        mesh = trimesh.creation.uv_sphere(radius=size[0], count=[_SEGMENTS // 2, _SEGMENTS])
    elif kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        mesh = trimesh.creation.uv_sphere(radius=1.0, count=[_SEGMENTS // 2, _SEGMENTS])
        mesh.apply_scale(size[:3])
    elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        mesh = trimesh.creation.cylinder(radius=size[0], height=2 * size[1], sections=_SEGMENTS)
    elif kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        mesh = trimesh.creation.capsule(
            height=2 * size[1], radius=size[0], count=[_SEGMENTS, _SEGMENTS]
        )
    else:
        return None
    positions = np.asarray(mesh.vertices, dtype=np.float32)
    faces = np.asarray(mesh.faces, dtype=np.uint32)
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        # flat caps and a smooth side: split the mesh by face so each keeps its own normals
        corners = positions[faces.reshape(-1)]
        face_normals = np.asarray(mesh.face_normals, dtype=np.float32)
        side = np.abs(face_normals[:, 2]) < 0.5
        radial = corners.copy()
        radial[:, 2] = 0.0
        corner_normals = np.repeat(face_normals, 3, axis=0)
        side_corners = np.repeat(side, 3)
        corner_normals[side_corners] = _unit(radial[side_corners])
        table = np.hstack([corners, corner_normals])
        unique, inverse = np.unique(table, axis=0, return_inverse=True)
        positions, normals = unique[:, :3], unique[:, 3:]
        faces = inverse.reshape(-1, 3).astype(np.uint32)
    else:
        normals = np.asarray(mesh.vertex_normals, dtype=np.float32)
    uvs = positions[:, :2] * np.asarray(repeat, dtype=np.float32)  # planar: tiles per metre
    return Triangles(
        positions.astype(np.float32),
        _unit(normals).astype(np.float32),
        uvs.astype(np.float32),
        faces,
    )


def _flat_normals(corners: np.ndarray) -> np.ndarray:
    tri = corners.reshape(-1, 3, 3)
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    return np.repeat(_unit(normals), 3, axis=0).astype(np.float32)


def _unit(vectors: np.ndarray) -> np.ndarray:
    vectors = np.asarray(vectors, dtype=np.float64)
    length = np.linalg.norm(vectors, axis=1, keepdims=True)
    fallback = np.zeros_like(vectors)
    fallback[:, 2] = 1.0
    return np.where(length > 1e-12, vectors / np.maximum(length, 1e-12), fallback)


def matrix_to_quat_wxyz(rotation: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of a rotation matrix."""
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.asarray(rotation, dtype=np.float64).reshape(-1))
    return quat


def quat_from_to(
    source: Sequence[float] | np.ndarray, target: Sequence[float] | np.ndarray
) -> np.ndarray:
    """The shortest rotation (w, x, y, z) taking direction ``source`` onto ``target``."""
    a = np.asarray(source, dtype=float) / np.linalg.norm(source)
    b = np.asarray(target, dtype=float)
    norm = np.linalg.norm(b)
    if norm < 1e-12:
        return np.array([1.0, 0.0, 0.0, 0.0])
    b = b / norm
    cross = np.cross(a, b)
    dot = float(np.dot(a, b))
    if dot < -1 + 1e-9:  # opposite: half a turn about any axis normal to a
        axis = np.cross(a, [1.0, 0.0, 0.0])
        if np.linalg.norm(axis) < 1e-6:
            axis = np.cross(a, [0.0, 1.0, 0.0])
        axis /= np.linalg.norm(axis)
        return np.array([0.0, *axis])
    quat = np.array([1.0 + dot, *cross])
    return quat / np.linalg.norm(quat)


def degrees(radians: float) -> float:
    return math.degrees(float(radians))
