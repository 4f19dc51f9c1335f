"""Turn a parametric asset design (parts + facts) into a library :class:`AssetBundle`.

The design may be drawn in any frame; assembly moves it so that the bounding box of the
visual meshes is centred on the origin in X and Y with its bottom at z = 0 (the asset frame of
holomj), merges the parts of each material into one OBJ, and derives colliders, support
surfaces, size and density.

Textures: the parts of a wood, fabric, velvet, leather, marble, tile, brick, carpet or concrete
material get box-projected UVs in metres and the matching procedural pattern (see
:mod:`.textures`), tinted so that it averages to the material's colour (the visual part's
``rgba`` is that tint: the colour divided by the pattern's mean, capped at 1);
``AssetDesign.textured=False`` or a material with ``pattern="plain"`` keeps plain colours.

Colliders: every collider lies inside the visual, and the colliders must cover the visual
surface: where a part's own colliders (or a visual-only part's lack of them) leave more than
:data:`COVER_TARGET_M` of it outside every collider, assembly gives that part its colliders
back (a visual-only part) or the convex hull of its mesh (a convex part). The remaining gap
(:mod:`asset_pipeline.collider_audit`) is recorded as ``collider_gap_m``.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from asset_pipeline.collider_audit import ColliderGap, collider_gap, mesh_gaps, round_gap
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural.asset_records import (
    LICENSE,
    SOURCE,
    check_clearance,
    check_inside,
    collision_record,
    meta_round,
    surface_record,
)
from asset_pipeline.procedural.obj_writer import merge_meshes, obj_bytes, rounded
from asset_pipeline.procedural.parts import (
    Collider,
    Mesh,
    Part,
    RecipeMaterial,
    Vec3,
    hull_collider,
)
from asset_pipeline.procedural.textures import (
    pattern_of,
    pattern_png,
    texture_file,
    textured_mesh,
    tinted,
)
from holomj.spec.assets import AssetMeta, VisualPart
from holomj.spec.base import validate_model


@dataclass(frozen=True)
class AssetDesign:
    """Everything needed to build one procedural asset."""

    id: str
    category: str
    description: str
    mass_kg: float
    friction: float
    placement: tuple[str, ...]
    parts: tuple[Part, ...]
    attributes: tuple[tuple[str, str], ...] = ()  # honoured (colour, material, shape, style)
    proxy: bool = False  # a stand-in from a parametric family (asset_pipeline.procedural.proxies)
    textured: bool = True  # False: every material a plain colour, no textures


COVER_TARGET_M = 0.003  # visual surface a part's colliders may leave uncovered before a fix
MIN_HULL_VERTICES = 64  # MuJoCo's default maxhullvert; raised for assets with bigger hulls
_MAX_CONVEX_CHECK = 512  # meshes with more vertices are not tried as convex hulls


# Small objects that only make sense standing (spawn-and-drop rejects them tipped over).
UPRIGHT_CATEGORIES = frozenset(
    {
        "mug",
        "cup",
        "bowl",
        "bottle",
        "vase",
        "candle",
        "small_plant",
        "potted_plant",
        "desk_lamp",
        "floor_lamp",
        "pot",
        "laptop",
    }
)


def assemble(design: AssetDesign, expected_size: Vec3 | None = None) -> AssetBundle:
    """Build the bundle (metadata + OBJ files + textures) of ``design``.

    With ``expected_size`` the visual bounding box must match it within 1 mm. Every support
    surface must have :data:`CLEARANCE` of free space above it (no part's bounds reach into
    the prism over its polygon); a violation is a bug in the design and raises ValueError.
    """
    parts = centred_parts(design.parts)
    files: dict[str, bytes] = {}
    visual, visual_meshes = material_visuals(design, parts, files)
    vertices = np.concatenate([m.vertices for m in visual_meshes])
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    if expected_size is not None and np.any(np.abs(high - low - expected_size) > 1e-3):
        raise ValueError(
            f"{design.id}: generated size {tuple(np.round(high - low, 4))} differs from the "
            f"requested {expected_size}"
        )
    colliders, gap = covering_colliders(parts)
    check_inside(design.id, colliders, low, high)
    check_clearance(design.id, parts)
    collision = []
    hulls: dict[int, np.ndarray] = {}
    for k, collider in enumerate(colliders):
        name = f"hull_{k:02d}.obj"
        part, hull = collision_record(collider, name)
        if hull is not None:
            files[name] = hull[0]
            hulls[k] = hull[1]
        collision.append(part)
    volume = sum(c.volume_m3 for c in collision)
    surfaces = [surface_record(s) for part in parts for s in part.surfaces()]
    surfaces.sort(key=lambda s: (s.height, s.polygon))
    meta = {
        "id": design.id,
        "category": design.category,
        "description": design.description,
        "size": [meta_round(v) for v in high - low],
        "mass_kg": design.mass_kg,
        "density_kg_m3": round(design.mass_kg / volume, 3),
        "friction": design.friction,
        "placement": list(design.placement),
        "upright": design.category in UPRIGHT_CATEGORIES,
        "visual": [v.model_dump(mode="json") for v in visual],
        "collision": [c.model_dump(mode="json") for c in collision],
        "surfaces": [s.model_dump(mode="json") for s in surfaces],
        "source": SOURCE,
        "license": LICENSE,
        "collider_gap_m": round_gap(gap.distance_m),
    }
    if hulls:
        meta["maxhullvert"] = max(MIN_HULL_VERTICES, *(len(h) for h in hulls.values()))
    if design.attributes:
        meta["attributes"] = dict(design.attributes)
    if design.proxy:
        meta["proxy"] = True
    return AssetBundle(meta=validate_model(AssetMeta, meta, design.id), files=files)


def material_visuals(
    design: AssetDesign, parts: Sequence[Part], files: dict[str, bytes], prefix: str = ""
) -> tuple[list[VisualPart], list[Mesh]]:
    """One OBJ file per material of ``parts`` (added to ``files``, named ``<prefix>_<material>``
    or ``<material>``, textured when the design is) and its visual record; also the meshes."""
    by_material: dict[str, tuple[RecipeMaterial, list[Mesh]]] = {}
    for part in parts:
        mesh = part.mesh()
        if mesh is not None:
            by_material.setdefault(part.material.name, (part.material, []))[1].append(mesh)
    visual, meshes = [], []
    for name in sorted(by_material):
        material, group = by_material[name]
        pattern = pattern_of(material) if design.textured else None
        if pattern is not None:
            group = [textured_mesh(m, pattern) for m in group]
        mesh = rounded(merge_meshes(group))
        meshes.append(mesh)
        filename = f"{prefix}_{name}.obj" if prefix else f"{name}.obj"
        files[filename] = obj_bytes(mesh, comment=f"{design.id}: {name} ({SOURCE}, {LICENSE})")
        rgba, texture = material.rgba, None
        if pattern is not None:  # the tint that, times the pattern, averages to the colour
            texture = texture_file(pattern)
            files[texture] = pattern_png(pattern)
            r, g, b, a = tinted(rgba, pattern)
            rgba = (r, g, b, a)
        visual.append(
            VisualPart(
                mesh=filename,
                rgba=rgba,
                texture=texture,
                specular=material.specular,
                shininess=material.shininess,
            )
        )
    return visual, meshes


def covering_colliders(
    parts: Sequence[Part], target: float = COVER_TARGET_M
) -> tuple[list[Collider], ColliderGap]:
    """The colliders of ``parts``, completed so that they cover every visual part, and the gap
    they leave (measured on the parts as drawn, before the files round them to 10 microns).

    Parts whose visual surface reaches more than ``target`` outside every collider get their
    own colliders back if they are visual-only (a net, a blind's slats, a lamp's glass); those
    still uncovered and convex get the convex hull of their mesh in place of their colliders
    (a slanted board or an elliptic top whose inscribed boxes leave slivers) where that leaves
    less uncovered. Parts neither helps keep their colliders; the gap reports what they leave.
    """
    own = [part.colliders() for part in parts]
    meshes = {i: mesh for i, part in enumerate(parts) if (mesh := part.mesh()) is not None}
    shown = list(meshes)
    pieces = {i: (m.vertices, m.faces) for i, m in meshes.items()}

    def measure(which: list[int]) -> dict[int, float]:
        everything = [c for group in own for c in group]
        if not everything:
            return {i: math.inf for i in which}
        found, _, _ = mesh_gaps([pieces[i] for i in which], everything, stop_above=target)
        return dict(zip(which, found.tolist(), strict=True))

    everything = [c for group in own for c in group]
    if everything:
        first, point, count = mesh_gaps([pieces[i] for i in shown], everything, stop_above=target)
        if first.max() <= target:  # exact: only gaps above the target are cut short
            return everything, ColliderGap(float(first.max()), point, count)
        gaps = dict(zip(shown, first.tolist(), strict=True))
    else:
        gaps = {i: math.inf for i in shown}
    bad = [i for i in shown if gaps[i] > target]
    if bad:
        for i in bad:
            forced = with_collision(parts[i])
            colliders = forced.colliders() if forced is not None else []
            if colliders:
                own[i] = colliders
        gaps.update(measure(bad))
        convex = [i for i in bad if gaps[i] > target and is_convex(meshes[i])]
        if convex:
            before = {i: (own[i], gaps[i]) for i in convex}
            for i in convex:
                own[i] = [hull_collider(pieces[i][0])]
            after = measure(convex)
            for i in convex:
                if after[i] >= before[i][1] - 1e-6:
                    own[i] = before[i][0]  # the hull does not help: keep what it had
    everything = [c for group in own for c in group]
    if not everything:
        raise ValueError("a design needs at least one collider")
    return everything, collider_gap([pieces[i] for i in shown], everything)


def with_collision(part: Part) -> Part | None:
    """``part`` with its colliders switched on (through role wrappers), or None if it has no
    ``collide`` switch or it is on already."""
    if not dataclasses.is_dataclass(part) or isinstance(part, type):
        return None
    values = {f.name: getattr(part, f.name) for f in dataclasses.fields(part)}
    if "collide" in values:
        if values["collide"]:
            return None
        return dataclasses.replace(part, collide=True)
    if "part" in values:
        inner = with_collision(values["part"])
        return None if inner is None else dataclasses.replace(part, part=inner)
    return None


def is_convex(mesh: Mesh, tolerance: float = 1e-7) -> bool:
    """True if ``mesh`` (closed, faces outward) bounds a convex solid: no vertex lies in front
    of any face's plane. Meshes with many vertices are not checked (False)."""
    if len(mesh.vertices) > _MAX_CONVEX_CHECK or len(mesh.faces) < 4:
        return False
    tri = mesh.vertices[mesh.faces]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-14
    normals = normals[keep] / lengths[keep, None]
    heights = np.einsum("fvk,fk->fv", mesh.vertices[None, :, :] - tri[keep, 0][:, None, :], normals)
    return bool(np.all(heights <= tolerance))


def assemble_all(designs: Sequence[AssetDesign]) -> list[AssetBundle]:
    """Assemble every design, in order."""
    return [assemble(design) for design in designs]


def centred_parts(parts: Sequence[Part]) -> list[Part]:
    """The parts moved into the asset frame: visual bbox centred in X, Y, bottom at z = 0."""
    bounds = [b for b in (p.bounds() for p in parts) if b is not None]
    if not bounds:
        raise ValueError("a design needs at least one visual part")
    low = np.min([b[0] for b in bounds], axis=0)
    high = np.max([b[1] for b in bounds], axis=0)
    offset: Vec3 = (
        -0.5 * float(low[0] + high[0]),
        -0.5 * float(low[1] + high[1]),
        -float(low[2]),
    )
    return [p.translated(offset) for p in parts]
