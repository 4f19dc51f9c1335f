"""Assemble an articulated design into a library :class:`AssetBundle`.

Like :func:`asset_pipeline.procedural.assembly.assemble`, but the parts are grouped by link:
the carcass (parts outside any :class:`~.links.Moving`) becomes the asset's ``visual``,
``collision`` and ``surfaces``; every link becomes an
:class:`~holomj.spec.assets.ArticulatedPart` with its own meshes (``<link>_<material>.obj``),
colliders (``<link>_hull_NN.obj`` for hulls), joint and handle; the tops of
:class:`~.links.Inside` parts become ``articulation.interior`` surfaces. The visual bounding
box of the whole closed asset is its size and is centred as usual (front +X, bottom z = 0).

Checks (a violation is a bug in the design and raises ValueError): the size as requested;
every collider inside the bounds; the usual free height above outer surfaces; a free height
above interior surfaces (recorded as ``clearance_m``); moving parts clear of the carcass and of
each other at the closed pose (no collider pair of different bodies closer than
:data:`CLOSED_GAP`, a part and the body it hangs on included although the compiled model
excludes their contacts).

Joints are finished here, where the parts' masses are known: hinges get damping in proportion
to their handle's lever (:func:`~.links.damped`) and horizontal hinges their counterbalance
(:func:`~.links.balanced`); the moving parts weigh their density times their collider volume,
at most :data:`MAX_PART_SHARE` of the asset, the carcass the rest.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from asset_pipeline.collider_audit import round_gap
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural.articulated.links import Link, balanced, damped, unwrapped
from asset_pipeline.procedural.assembly import (
    MIN_HULL_VERTICES,
    AssetDesign,
    centred_parts,
    covering_colliders,
    material_visuals,
)
from asset_pipeline.procedural.asset_records import (
    CLEARANCE,
    LICENSE,
    PROUD,
    SOURCE,
    check_clearance,
    check_inside,
    collision_record,
    meta_round,
    surface_record,
)
from asset_pipeline.procedural.parts import Collider, Mesh, Part, RecipeSurface, Vec3
from holomj.spec.assets import AssetMeta, CollisionPart, SupportSurface, VisualPart
from holomj.spec.base import validate_model

CLOSED_GAP = 0.0015  # metres between colliders of different bodies at the closed pose
MAX_PART_SHARE = 0.8  # the moving parts weigh at most this share of the asset
CARCASS = ""  # the group key of the carcass


@dataclass
class _Group:
    """The parts of one body: the carcass or one link."""

    link: Link | None
    parts: list[Part]


def assemble_articulated(design: AssetDesign, expected_size: Vec3 | None = None) -> AssetBundle:
    """Build the bundle of an articulated ``design`` (see the module docstring)."""
    parts = centred_parts(design.parts)
    groups = _groups(parts)
    for group in groups.values():
        if group.link is not None:
            group.link = damped(group.link)
    if len(groups) < 2:
        raise ValueError(f"{design.id}: an articulated design needs at least one moving part")
    files: dict[str, bytes] = {}
    all_meshes: list[Mesh] = []
    visuals: dict[str, list[VisualPart]] = {}
    for key, group in groups.items():
        visuals[key], meshes = _visuals(design, key, group.parts, files)
        all_meshes += meshes
    vertices = np.concatenate([m.vertices for m in all_meshes])
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    if expected_size is not None and np.any(np.abs(high - low - expected_size) > 1e-3):
        raise ValueError(
            f"{design.id}: generated size {tuple(np.round(high - low, 4))} differs from the "
            f"requested {expected_size}"
        )
    colliders: dict[str, list[Collider]] = {}
    gap = 0.0
    for key, group in groups.items():
        colliders[key], covered = covering_colliders(group.parts)
        gap = max(gap, covered.distance_m)
        check_inside(design.id, colliders[key], low, high)
    check_clearance(design.id, [p for p in parts if unwrapped(p)[2] is None])
    _check_closed_gaps(design.id, groups, colliders)
    collision, hull_sizes = _collision(colliders, files)
    masses, carcass_mass = _masses(design, groups, collision)
    carcass_volume = sum(c.volume_m3 for c in collision[CARCASS])
    for key, group in groups.items():
        if group.link is not None and group.link.joint.balance:  # fit its counterbalance
            link = group.link
            group.link = replace(
                link, joint=balanced(link.joint, masses[key], _centre(collision[key]))
            )
    surfaces = _outer_surfaces(design.id, parts)
    articulation = {
        "parts": [
            _part_record(group.link, visuals[key], collision[key], masses[key])
            for key, group in groups.items()
            if group.link is not None
        ],
        "interior": _interior(design.id, parts),
    }
    meta = {
        "id": design.id,
        "category": design.category,
        "description": design.description,
        "size": [meta_round(v) for v in high - low],
        "mass_kg": design.mass_kg,
        "density_kg_m3": round(carcass_mass / carcass_volume, 3),
        "friction": design.friction,
        "placement": list(design.placement),
        "upright": True,
        "visual": [v.model_dump(mode="json") for v in visuals[CARCASS]],
        "collision": [c.model_dump(mode="json") for c in collision[CARCASS]],
        "surfaces": [s.model_dump(mode="json") for s in surfaces],
        "source": SOURCE,
        "license": LICENSE,
        "collider_gap_m": round_gap(gap),
        "articulation": articulation,
    }
    if hull_sizes:
        meta["maxhullvert"] = max(MIN_HULL_VERTICES, *hull_sizes)
    if design.attributes:
        meta["attributes"] = dict(design.attributes)
    return AssetBundle(meta=validate_model(AssetMeta, meta, design.id), files=files)


def _collision(
    colliders: dict[str, list[Collider]], files: dict[str, bytes]
) -> tuple[dict[str, list[CollisionPart]], list[int]]:
    """The collision records of every body (hull OBJ files go into ``files``) and the vertex
    counts of the hulls."""
    collision: dict[str, list[CollisionPart]] = {}
    hull_sizes: list[int] = []
    for key, found in colliders.items():
        collision[key] = []
        prefix = f"{key}_" if key else ""
        for k, collider in enumerate(found):
            name = f"{prefix}hull_{k:02d}.obj"
            part, hull = collision_record(collider, name)
            if hull is not None:
                files[name] = hull[0]
                hull_sizes.append(len(hull[1]))
            collision[key].append(part)
    return collision, hull_sizes


def _masses(
    design: AssetDesign, groups: dict[str, _Group], collision: dict[str, list[CollisionPart]]
) -> tuple[dict[str, float], float]:
    """The mass of every moving body (its link's density times its collision volume, scaled
    down so that they weigh at most :data:`MAX_PART_SHARE` of the asset) and the carcass's."""
    masses = {
        key: group.link.density * sum(c.volume_m3 for c in collision[key])
        for key, group in groups.items()
        if group.link is not None
    }
    moving = sum(masses.values())
    if moving > MAX_PART_SHARE * design.mass_kg:  # keep the carcass the heavier part
        masses = {k: m * MAX_PART_SHARE * design.mass_kg / moving for k, m in masses.items()}
    return masses, design.mass_kg - sum(masses.values())


def _outer_surfaces(asset_id: str, parts: list[Part]) -> list[SupportSurface]:
    """The outer support surfaces: those of carcass parts not inside it (a moving part with
    one is an error: wrap it in Inside)."""
    outer = [
        s
        for p in parts
        if unwrapped(p)[1] is None and unwrapped(p)[2] is None
        for s in p.surfaces()
    ]
    stray = [
        p for p in parts if unwrapped(p)[1] is not None and unwrapped(p)[2] is None and p.surfaces()
    ]
    if stray:
        raise ValueError(f"{asset_id}: a moving part has an outer surface; wrap it in Inside")
    return sorted((surface_record(s) for s in outer), key=lambda s: (s.height, s.polygon))


def _centre(collision: list) -> Vec3:
    """The centre of mass of colliders of one density (volume-weighted centres)."""
    volumes = np.array([c.volume_m3 for c in collision])
    centres = np.array([c.pos for c in collision], dtype=float)
    centre = volumes @ centres / volumes.sum()
    return (float(centre[0]), float(centre[1]), float(centre[2]))


def _groups(parts: Sequence[Part]) -> dict[str, _Group]:
    """Parts by body, the carcass first, links in order of first appearance (parents first)."""
    groups: dict[str, _Group] = {CARCASS: _Group(None, [])}
    for part in parts:
        link = unwrapped(part)[1]
        key = CARCASS if link is None else link.name
        if key not in groups:
            groups[key] = _Group(link, [])
        elif link is not None and groups[key].link != link:
            raise ValueError(f"link {key!r} is described twice, differently")
        groups[key].parts.append(part)
    names = list(groups)
    for key, group in groups.items():
        parent = group.link.parent if group.link is not None else None
        if parent is not None and (parent not in groups or names.index(parent) > names.index(key)):
            raise ValueError(f"link {key!r}: its parent {parent!r} must come before it")
    return groups


def _visuals(
    design: AssetDesign, key: str, parts: list[Part], files: dict[str, bytes]
) -> tuple[list[VisualPart], list[Mesh]]:
    """The OBJ files (added to ``files``) and visual records of one body's parts."""
    visual, meshes = material_visuals(design, parts, files, prefix=key)
    if not visual:
        raise ValueError(f"{design.id}: body {key or 'carcass'!r} has no visual part")
    return visual, meshes


def _part_record(link: Link, visual: list[VisualPart], collision: list, mass: float) -> dict:
    joint = link.joint
    record = {
        "name": link.name,
        "kind": link.kind,
        "parent": link.parent,
        "joint": {
            "name": link.joint_name,
            "type": joint.type,
            "axis": [meta_round(v) for v in joint.axis],
            "anchor": [meta_round(v) for v in joint.anchor],
            "range": [meta_round(v) for v in joint.range],
            "closed": 0.0,
            "damping": meta_round(joint.damping),
            "frictionloss": meta_round(joint.frictionloss),
            "armature": meta_round(joint.armature),
            "stiffness": meta_round(joint.stiffness),
            "springref": meta_round(joint.springref),
        },
        "mass_kg": float(f"{mass:.4g}"),
        "visual": [v.model_dump(mode="json") for v in visual],
        "collision": [c.model_dump(mode="json") for c in collision],
    }
    if link.handle is not None:
        h = link.handle
        record["handle"] = {
            "pos": [meta_round(v) for v in h.pos],
            "quat": [meta_round(v) for v in h.quat],
            "pull": [meta_round(v) for v in h.pull],
            "length_m": meta_round(h.length),
        }
    return record


def _interior(asset_id: str, parts: Sequence[Part]) -> list[dict]:
    """The interior surfaces: on the carcass or a link, with the joints to open and the free
    height above (to the nearest part over the polygon at the closed pose)."""
    joints = {}
    for part in parts:
        link = unwrapped(part)[1]
        if link is not None:
            joints[link.name] = link.joint_name
    boxes = [b for p in parts for b in _bounds_of(p)]
    found = []
    for part in parts:
        _, link, behind = unwrapped(part)
        if behind is None:
            continue
        for surface in part.surfaces():
            clearance = _clearance(surface, boxes)
            if clearance < CLEARANCE:
                raise ValueError(
                    f"{asset_id}: the interior surface at z = {surface.height:.3f} has only "
                    f"{clearance:.3f} m free above it"
                )
            record = surface_record(surface).model_dump(mode="json")
            record["part"] = link.name if link is not None else None
            record["behind"] = [joints[name] for name in behind]
            record["clearance_m"] = meta_round(min(clearance, 10.0))
            found.append(record)
    found.sort(key=lambda s: (s["part"] or "", s["height"], s["polygon"]))
    return found


def _bounds_of(part: Part) -> list[tuple[np.ndarray, np.ndarray]]:
    boxes = []
    bounds = part.bounds()
    if bounds is not None:
        boxes.append((np.asarray(bounds[0]), np.asarray(bounds[1])))
    for c in part.colliders():
        half = np.asarray(c.half_extents())
        boxes.append((np.asarray(c.pos) - half, np.asarray(c.pos) + half))
    return boxes


def _clearance(surface: RecipeSurface, boxes: list[tuple[np.ndarray, np.ndarray]]) -> float:
    xy = np.asarray(surface.polygon)
    (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
    h = surface.height
    above = [
        low[2] - h
        for low, high in boxes
        if high[2] > h + PROUD
        and low[0] < x1 - 1e-6
        and high[0] > x0 + 1e-6
        and low[1] < y1 - 1e-6
        and high[1] > y0 + 1e-6
    ]
    return min(above) if above else math.inf


def _check_closed_gaps(
    asset_id: str, groups: dict[str, _Group], colliders: dict[str, list[Collider]]
) -> None:
    """No two colliders of different bodies closer than CLOSED_GAP at the closed pose (a
    conservative test of their bounding boxes), a link and its parent included although their
    contacts are excluded in the model: a closed door stands clear of its carcass."""
    for ka, kb in itertools.combinations(groups, 2):
        for ca in colliders[ka]:
            for cb in colliders[kb]:
                if _boxes_closer(ca, cb, CLOSED_GAP):
                    raise ValueError(
                        f"{asset_id}: {ka or 'carcass'} and {kb or 'carcass'} touch at the "
                        f"closed pose ({ca.pos} and {cb.pos})"
                    )


def _boxes_closer(a: Collider, b: Collider, gap: float) -> bool:
    ha, hb = np.asarray(a.half_extents()), np.asarray(b.half_extents())
    d = np.abs(np.asarray(a.pos) - np.asarray(b.pos)) - ha - hb
    return bool(np.all(d < gap - 1e-9))
