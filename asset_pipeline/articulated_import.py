"""Import an articulated file (URDF or MJCF) as one articulated asset (nothing is written).

``import_articulated(path, asset_id, options)`` reads the file's kinematic tree
(:mod:`asset_pipeline.urdf`, :mod:`asset_pipeline.mjcf_import`) and:

1. **bodies**: the root link(s) and everything fixed to them are the *carcass*; every moving
   joint (hinge or slide) starts a *part*: its child link and everything fixed to it. A part
   under another part hangs on it (``parent``). A moving link without geometry (PartNet-
   Mobility's ``link_N_helper`` of a screw joint) takes its child links' geometry, which then
   moves on its joint only (the child's joint is dropped, with a warning); one without any is
   dropped.
2. **closed pose**: a joint's *closed* value is the pose the file gives (URDF: 0, MJCF:
   ``qpos0``) clamped into its range. The part's geometry (and its sub-parts) is moved there;
   the opening direction is the one with more travel (the axis is flipped when that is the
   negative one), so positive values open and 0 is closed, as in holomj's own assets. An
   unlimited (continuous) hinge gets the range (-pi, pi).
3. **frame**: Z up (``--up`` converts a Y-up file), metres (``--size`` scales uniformly: needed
   for PartNet-Mobility, whose models are normalised), origin at the centre of the footprint at
   the bottom of the closed asset. The front is ``--front`` unless that is the default ``+x``:
   then it is the side the parts open towards (the mean horizontal direction in which the
   parts' centres move as they open), so PartNet-Mobility models (front -X) turn to face +X.
4. **per body** as for any import: repair, CoACD (each body on its own, with the preset's
   settings, timeout and fallbacks), hull post-processing, visual meshes (``visual_K.obj`` for
   the carcass, ``<part>_visual_K.obj`` and ``<part>_hull_KK.obj`` for parts).
5. **mass**: the whole asset's mass as for a mesh import (category material x material volume
   of all bodies, clamped to the category's range; ``--mass`` or a sidecar wins), shared among
   the bodies by their material volume, the moving parts at most 80 %.
6. **joints**: the file's damping, friction loss and armature where it gives them (> 0), else
   holomj's defaults for furniture (a hinge damped by 20 N m s/rad per metre of handle lever,
   0.6 N m friction; a slide 60 N s/m, 3 N); a hinge whose axis is not vertical (a lid, a
   drop-down door) gets the counterbalance spring of the procedural assets unless the file
   gives a stiffness, so it stays where it is left.
7. **handles** by the heuristic of :mod:`asset_pipeline.handles`; **kinds** from PartNet-
   Mobility's ``semantics.txt`` label or the link and joint names (drawer, door, lid, rack,
   seat; knobs, buttons, switches, levers and wheels are flaps), else from the motion: a
   horizontal slide -> drawer, a vertical one -> lid when the part reaches the asset's top,
   else rack; an unlimited hinge -> flap; a vertical hinge -> door; a horizontal hinge -> lid
   when the part reaches the asset's top, else door.
8. **surfaces**: the carcass's upward surfaces (:func:`asset_pipeline.surfaces.support_surfaces`)
   that have carcass above them and a part in front are *interior* (``behind`` the joints of
   those parts), the others outer ``surfaces``; a part's upward surfaces with something above
   them at the closed pose (a drawer bottom) are interior surfaces of that part, behind its
   joint and its ancestors'. Interior surfaces with less than :data:`MIN_CLEARANCE_M` free above
   are left out. The free height (``clearance_m``) is measured at the closed pose.

Parts whose colliders overlap another body's (other than the one they hang on) at the closed
pose are reported in a warning: they would collide in the model. A file without moving joints
becomes a rigid asset (with a warning).
"""

from __future__ import annotations

import hashlib
import math
import re
import time
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from asset_pipeline import annotate, physical
from asset_pipeline.decompose import decompose
from asset_pipeline.handles import derive_grasp, lever_m
from asset_pipeline.hulls import collision_records, postprocess
from asset_pipeline.import_records import (
    ImportedAsset,
    check_asset_id,
    physical_record,
    visual_records,
)
from asset_pipeline.kinematics import JointInfo, Kinematics, joint_motion, transformed
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.load import Part
from asset_pipeline.mjcf_import import check_mjcf, load_mjcf, mjcf_files, root_tag
from asset_pipeline.normalise import _UP, normalise
from asset_pipeline.proximity import MeshProximity
from asset_pipeline.repair import Repaired, repair
from asset_pipeline.surfaces import _first_hits, support_surfaces
from asset_pipeline.urdf import load_urdf, read_urdf
from holomj.errors import FormatError

CARCASS = ""
MAX_PART_SHARE = 0.8
MIN_CLEARANCE_M = 0.05
VERTICAL_COS = math.cos(math.radians(20.0))
FRONT_MARGIN_M = 0.05  # a part "in front" of a surface reaches this close to its front edge
RESERVED_PARTS = frozenset({"body"})  # holomj.mjcf.names: <object>/body is the carcass
RESERVED_JOINTS = frozenset({"freejoint"})
# holomj's defaults for furniture (asset_pipeline.procedural.articulated.links).
HINGE_DAMPING_PER_M = 20.0
DOOR_FRICTIONLOSS = 0.6
DRAWER_DAMPING = 60.0
DRAWER_FRICTIONLOSS = 3.0
LID_FRICTIONLOSS = 0.5
ARMATURE = 0.01
# PartNet-Mobility's model_cat -> holomj category (others: snake_case of model_cat).
PARTNET_CATEGORIES = {
    "StorageFurniture": "cabinet",
    "Refrigerator": "fridge",
    "WashingMachine": "washing_machine",
    "TrashCan": "trash_can",
    "KitchenPot": "pot",
    "Display": "monitor",
    "FoldingChair": "chair",
    "Dispenser": "soap_dispenser",
}
_KIND_WORDS = (
    ("drawer", "drawer"),
    ("rack", "rack"),
    ("seat", "seat"),
    ("lid", "lid"),
    ("cover", "lid"),
    ("door", "door"),
    ("flap", "flap"),
    ("knob", "flap"),
    ("button", "flap"),
    ("switch", "flap"),
    ("lever", "flap"),
    ("wheel", "flap"),
)


def articulated_format(path: Path) -> str | None:
    """``"urdf"`` or ``"mjcf"`` when ``path`` is an articulated description file, else None."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".urdf":
        return "urdf"
    if suffix in (".xml", ".mjcf") and path.is_file():
        tag = root_tag(path)
        if tag == "mujoco":
            return "mjcf"
        if tag == "robot":
            return "urdf"
    return None


def check_articulated_file(path: Path) -> None:
    """Check the file's structure (URDF: its tree and that every mesh exists; MJCF: that
    MuJoCo loads it and its tree); a one-line FormatError naming file and element."""
    if articulated_format(path) == "mjcf":
        check_mjcf(Path(path))
    else:
        read_urdf(path)


def articulated_sources(path: Path) -> list[Path]:
    """The files an import of ``path`` reads besides itself (meshes, their materials and
    textures, PartNet-Mobility's ``meta.json`` and ``semantics.txt``), for cache keys."""
    path = Path(path)
    try:
        meshes = mjcf_files(path) if articulated_format(path) == "mjcf" else read_urdf(path).files()
    except FormatError:
        return []
    found: list[Path] = []
    for mesh in meshes:
        found.append(mesh)
        for companion in sorted(mesh.parent.glob(f"{mesh.stem}.*")):
            if companion.suffix.lower() in (".mtl", ".bin", ".png", ".jpg", ".jpeg"):
                found.append(companion)
    for extra in ("meta.json", "semantics.txt"):
        if (path.parent / extra).is_file():
            found.append(path.parent / extra)
    return list(dict.fromkeys(p for p in found if p != path))


@dataclass
class _Body:
    """The carcass or one moving part: links, joint (None: carcass), parent part, geometry."""

    name: str
    links: list[str]
    joint: JointInfo | None = None
    parent: str | None = None
    parts: list[Part] = field(default_factory=list)
    merged_joints: list[str] = field(default_factory=list)
    record: dict = field(default_factory=dict)


@dataclass
class _Built:
    """A body after repair and decomposition."""

    body: _Body
    repaired: Repaired
    colliders: list
    decomposition: Any
    quality: dict


def import_articulated(path: Path | str, asset_id: str, options: Any) -> Any:
    """Import the URDF or MJCF file ``path`` as asset ``asset_id`` with ``options`` (an
    :class:`~asset_pipeline.import_records.ImportOptions`); see the module docstring."""
    path = Path(path)
    where = str(path)
    check_asset_id(asset_id)
    timings: dict[str, float] = {}
    clock = time.perf_counter()

    def lap(name: str) -> None:
        nonlocal clock
        now = time.perf_counter()
        timings[name] = round(now - clock, 3)
        clock = now

    sidecar_path = options.sidecar if options.sidecar is not None else annotate.find_sidecar(path)
    sidecar = annotate.read_sidecar(Path(sidecar_path)) if sidecar_path else {}
    sidecar_where = str(sidecar_path) if sidecar_path else where
    fmt = articulated_format(path) or "urdf"
    kin = (
        load_mjcf(path, options.max_faces) if fmt == "mjcf" else load_urdf(path, options.max_faces)
    )
    warnings = list(kin.warnings)
    lap("load")
    carcass, parts = _bodies(kin, where, warnings)
    _close(parts, warnings)
    up_axis = options.up_axis or kin.up_axis
    front = options.front if options.front != "+x" else _front(parts, up_axis)
    everything = [carcass, *parts]
    counts = [len(b.parts) for b in everything]
    flat, frame = normalise(
        [p for b in everything for p in b.parts], where, up_axis, front, options.size
    )
    start = 0
    for body, count in zip(everything, counts, strict=True):
        body.parts, start = flat[start : start + count], start + count
        if body.joint is not None:
            body.joint = _moved_joint(body.joint, frame)
    lap("normalise")

    files: dict[str, bytes] = {}
    textures: dict[str, str] = {}
    built = [_build(body, options, files, textures, where) for body in everything]
    lap("decompose")

    guessed = physical.guess_category(path)
    if options.category:
        category, category_source = options.category, "option"
    elif sidecar.get("category"):
        category, category_source = str(sidecar["category"]), "sidecar"
    elif kin.category:
        category, category_source = _partnet_category(kin.category), "PartNet-Mobility meta.json"
    elif guessed:
        category, category_source = guessed, "file name"
    else:
        category, category_source = physical.DEFAULT_CATEGORY, "default"
    info = physical.category_info(category, frame.size)
    given = options.mass_kg
    if given is None:
        given = annotate.sidecar_number(sidecar, "mass_kg", sidecar_where)
    density = annotate.sidecar_number(sidecar, "density_kg_m3", sidecar_where)
    volumes = [sum(c.volume for c in b.colliders) for b in built]
    whole = trimesh.util.concatenate([b.repaired.physics for b in built])
    massed = physical.resolve_mass(info, whole, sum(volumes), given=given, density=density)
    masses = _share_mass(massed.mass_kg, built, info, volumes)
    lap("mass")

    asset_top = float(frame.size[2])
    part_records = []
    for b, mass in zip(built[1:], masses[1:], strict=True):
        part_records.append(_part_record(b, mass, kin, asset_top))
    surfaces, interior = _surfaces(built, warnings)
    _warn_touching(built, warnings)
    lap("surfaces")

    derived = {
        "id": asset_id,
        "category": category,
        "description": annotate.describe(category),
        "size": list(frame.size),
        "mass_kg": massed.mass_kg,
        "density_kg_m3": density if density is not None else massed.mass_kg / sum(volumes),
        "friction": info.friction,
        "placement": list(info.placement),
        "upright": info.upright,
        "front": "+x",
        "visual": built[0].body.record["visual"],
        "collision": built[0].body.record["collision"],
        "maxhullvert": max(4, *(q.quality["max_vertices_per_hull"] for q in built)),
        "surfaces": surfaces,
        "source": f"{path.name} ({fmt}, up {up_axis}, front {front} -> +x, "
        f"scale {frame.scale:.6g})",
    }
    if part_records:
        derived["articulation"] = {"parts": part_records, "interior": interior}
    else:
        warnings.append("no moving joint: imported as a rigid asset")
    explicit = {"category": options.category, "description": options.description}
    if options.mass_kg is not None:
        explicit["mass_kg"] = float(options.mass_kg)
    meta, meta_warnings = annotate.build_meta(derived, sidecar, explicit, sidecar_where)
    lap("annotate")
    warnings += massed.warnings + meta_warnings
    degraded = [
        f"{_label(b.body)}: {b.decomposition.degraded_reason}"
        for b in built
        if b.decomposition.degraded
    ]
    if degraded:
        warnings.append(f"degraded decomposition: {'; '.join(degraded)}")
    report = {
        "asset_id": asset_id,
        "source": {
            "file": str(path),
            "sha256": hashlib.sha256(path.read_bytes()).hexdigest(),
            "format": fmt,
            "partnet_mobility": kin.partnet,
            "links": len(kin.links),
            "joints": len(kin.joints),
            "vertices": kin.vertices,
            "faces": kin.faces,
            "sidecar": str(sidecar_path) if sidecar_path else None,
        },
        "normalisation": frame.as_report() | {"requested_size_m": options.size},
        "degraded": bool(degraded),
        "degraded_reason": "; ".join(degraded) or None,
        "bodies": [
            {
                "body": _label(b.body),
                "links": b.body.links,
                "repairs": b.repaired.stats,
                "watertight": b.repaired.watertight,
                "decomposition": {
                    "method": b.decomposition.method,
                    "preprocess_mode": b.decomposition.preprocess_mode,
                    "attempts": b.decomposition.attempts,
                },
                "quality": b.quality,
                "mass_kg": mass,
                **({"joint": b.body.record["joint_report"]} if b.body.joint else {}),
            }
            for b, mass in zip(built, masses, strict=True)
        ],
        "surfaces": [{"height": s["height"], "area_m2": s["area_m2"]} for s in surfaces],
        "interior_surfaces": [
            {"part": s["part"], "height": s["height"], "behind": s["behind"]} for s in interior
        ],
        "physical": physical_record(meta, info, massed, category_source),
        "files": {name: len(data) for name, data in sorted(files.items())},
        "timings_s": timings,
        "warnings": warnings,
    }
    return ImportedAsset(bundle=AssetBundle(meta=meta, files=files), report=report)


# --- 1. bodies --------------------------------------------------------------------------------
def _bodies(kin: Kinematics, where: str, warnings: list[str]) -> tuple[_Body, list[_Body]]:
    children = {j.child for j in kin.joints}
    roots = [name for name in kin.links if name not in children]
    carcass = _Body(CARCASS, list(roots))
    body_of = dict.fromkeys(roots, CARCASS)
    bodies: dict[str, _Body] = {CARCASS: carcass}
    part_names: set[str] = set(RESERVED_PARTS)
    for joint in kin.joints:
        owner = body_of[joint.parent]
        if joint.type == "fixed":
            body_of[joint.child] = owner
            bodies[owner].links.append(joint.child)
            continue
        name = _unique(_identifier(joint.child, "part"), part_names)
        body_of[joint.child] = name
        bodies[name] = _Body(name, [joint.child], joint, None if owner == CARCASS else owner)
    for body in bodies.values():
        body.parts = [p for link in body.links for p in kin.links[link].parts]
    for body in list(bodies.values()):  # parents first
        if body.joint is None or body.parts or body.name not in bodies:
            continue
        _absorb_children(body, bodies, warnings)
    if not carcass.parts:
        raise FormatError(
            f"the fixed part (root link {', '.join(repr(r) for r in roots)} and the links fixed "
            "to it) has no geometry: nothing holds the moving parts",
            where=where,
        )
    parts = [b for b in bodies.values() if b.joint is not None]
    joint_names: set[str] = set(RESERVED_JOINTS)
    for body in parts:
        body.record["joint_name"] = _unique(_identifier(body.joint.name, "joint"), joint_names)  # type: ignore[union-attr]
    return carcass, parts


def _absorb_children(body: _Body, bodies: dict[str, _Body], warnings: list[str]) -> None:
    """A moving body without geometry (PartNet-Mobility's ``link_N_helper`` of a screw joint)
    takes the geometry of the parts hanging on it, whose joints are dropped; with one such part
    it takes its name. Without any, it is dropped and what hangs on it moves to its parent."""
    assert body.joint is not None
    below = [b for b in bodies.values() if b.parent == body.name]
    for child in below:
        assert child.joint is not None
        body.parts += child.parts
        body.links += child.links
        body.merged_joints.append(child.joint.name)
        for other in bodies.values():
            if other.parent == child.name:
                other.parent = body.name
        del bodies[child.name]
        warnings.append(
            f"joint {child.joint.name!r} dropped: link {body.links[0]!r} carries no geometry "
            f"(a screw joint?), so link {child.links[0]!r} moves on joint {body.joint.name!r} "
            "only"
        )
    old = body.name
    if not body.parts:
        warnings.append(f"moving link {body.links[0]!r} has no geometry: dropped")
        del bodies[old]
        new = body.parent
    elif len(below) == 1 and below[0].name not in bodies:
        new = body.name = below[0].name
        items = [(new if key == old else key, value) for key, value in bodies.items()]
        bodies.clear()
        bodies.update(items)  # same order: parents stay before their parts
    else:
        return
    for other in bodies.values():
        if other.parent == old:
            other.parent = new


def _identifier(text: str, fallback: str) -> str:
    name = re.sub(r"[^A-Za-z0-9_]+", "_", text).strip("_")[:56]
    return name or fallback


def _unique(name: str, taken: set[str]) -> str:
    candidate, n = name, 1
    while candidate in taken:
        n += 1
        candidate = f"{name}_{n}"
    taken.add(candidate)
    return candidate


def _descendants(body: _Body, parts: list[_Body]) -> list[_Body]:
    found, frontier = [], [body.name]
    while frontier:
        name = frontier.pop()
        for other in parts:
            if other.parent == name:
                found.append(other)
                frontier.append(other.name)
    return found


# --- 2. closed pose ---------------------------------------------------------------------------
def _close(parts: list[_Body], warnings: list[str]) -> None:
    """Move every part to its closed value and make positive values open (module docstring)."""
    for body in parts:
        joint = body.joint
        assert joint is not None
        if joint.range is None:
            closed, sign, rel = joint.value, 1.0, (-math.pi, math.pi)
        else:
            low, high = joint.range
            closed = min(max(joint.value, low), high)
            if high - closed >= closed - low:
                sign, rel = 1.0, (low - closed, high - closed)
            else:
                sign, rel = -1.0, (closed - high, closed - low)
        shift = closed - joint.value
        if abs(shift) > 1e-12:
            motion = joint_motion(joint, shift)
            for moved in [body, *_descendants(body, parts)]:
                moved.parts = [transformed(p, motion) for p in moved.parts]
                if moved is not body and moved.joint is not None:
                    moved.joint = replace(
                        moved.joint,
                        anchor=motion[:3, :3] @ moved.joint.anchor + motion[:3, 3],
                        axis=motion[:3, :3] @ moved.joint.axis,
                    )
            warnings.append(
                f"{joint.where}: the file's pose ({joint.value:g}) is outside its range "
                f"{joint.range}; the part was moved to {closed:g}, taken as closed"
            )
        springref = None
        if joint.springref is not None:
            springref = sign * (joint.springref - closed)
        body.joint = replace(
            joint, axis=sign * joint.axis, range=rel, value=0.0, springref=springref
        )
        body.record["joint_report"] = {
            "file_joint": joint.name,
            "file_range": list(joint.range) if joint.range else None,
            "file_value": joint.value,
            "closed_file_value": closed,
            "axis_flipped": sign < 0,
            "merged_joints": body.merged_joints,
        }


# --- 3. frame ---------------------------------------------------------------------------------
def _front(parts: list[_Body], up_axis: str) -> str:
    """The source axis (after the up conversion) the parts open towards; +x when none does."""
    up = _UP[up_axis]
    total = np.zeros(2)
    for body in parts:
        joint = body.joint
        assert joint is not None
        if joint.type == "slide":
            move = joint.axis
        else:
            centre = np.concatenate([p.vertices for p in body.parts]).mean(axis=0)
            move = np.cross(joint.axis, centre - joint.anchor)
        flat = (up @ move)[:2]
        length = float(np.linalg.norm(flat))
        if length > 0.3 * max(float(np.linalg.norm(move)), 1e-12):
            total += flat / length
    if np.linalg.norm(total) < 1e-6:
        return "+x"
    if abs(total[0]) >= abs(total[1]):
        return "+x" if total[0] > 0 else "-x"
    return "+y" if total[1] > 0 else "-y"


def _moved_joint(joint: JointInfo, frame: Any) -> JointInfo:
    """``joint`` in the asset frame (``frame``: the Normalisation applied to the meshes)."""
    rot, scale = frame.rotation, frame.scale
    low, high = joint.range  # type: ignore[misc]
    if joint.type == "slide":
        low, high = low * scale, high * scale
    return replace(
        joint,
        axis=rot @ joint.axis,
        anchor=scale * (rot @ joint.anchor) + frame.translation,
        range=(low, high),
    )


# --- 4. meshes and colliders per body ---------------------------------------------------------
def _build(
    body: _Body, options: Any, files: dict[str, bytes], textures: dict[str, str], where: str
) -> _Built:
    repaired = repair(body.parts)
    if len(repaired.physics.faces) == 0:
        raise FormatError(f"{_label(body)}: the meshes have only degenerate faces", where=where)
    manifold = repaired.watertight and repaired.winding_consistent
    decomposition = decompose(repaired.physics, options.coacd, manifold)
    proximity = MeshProximity(repaired.physics)
    hullset = postprocess(decomposition.hulls, repaired.physics, proximity, repaired.watertight)
    prefix = f"{body.name}_" if body.name else ""
    visual = visual_records(repaired.visuals, files, textures, prefix)
    collision = collision_records(hullset.colliders, files, prefix)
    body.record.update(visual=visual, collision=collision)
    return _Built(body, repaired, hullset.colliders, decomposition, hullset.quality)


def _label(body: _Body) -> str:
    return f"part {body.name!r} (link {body.links[0]!r})" if body.name else "the fixed part"


# --- 5. mass ----------------------------------------------------------------------------------
def _share_mass(total: float, built: list[_Built], info: Any, volumes: list[float]) -> list[float]:
    """The carcass's and every part's mass: ``total`` shared by material volume."""
    shares = [physical.material_volume(b.repaired.physics, info.wall_m).volume_m3 for b in built]
    if not all(math.isfinite(s) and s > 0 for s in shares):
        shares = volumes
    whole = sum(shares)
    masses = [total * s / whole for s in shares]
    moving = sum(masses[1:])
    if moving > MAX_PART_SHARE * total:
        masses[1:] = [m * MAX_PART_SHARE * total / moving for m in masses[1:]]
        masses[0] = total - sum(masses[1:])
    return [float(f"{m:.6g}") for m in masses]


# --- 6 and 7. joints, handles, kinds ----------------------------------------------------------
def _part_record(built: _Built, mass: float, kin: Kinematics, asset_top: float) -> dict:
    body = built.body
    joint = body.joint
    assert joint is not None
    points = np.asarray(built.repaired.physics.vertices)
    grasp = derive_grasp(points, joint.type, joint.axis, joint.anchor)
    kind, kind_source = _kind(body, kin, points, asset_top)
    axis = joint.axis / np.linalg.norm(joint.axis)
    vertical = abs(float(axis[2])) >= VERTICAL_COS
    armature = joint.armature if joint.armature else ARMATURE
    if joint.type == "slide":
        damping = joint.damping or DRAWER_DAMPING
        friction = joint.frictionloss or DRAWER_FRICTIONLOSS
        stiffness, springref = joint.stiffness or 0.0, joint.springref or 0.0
    else:
        lever = lever_m(grasp.pos, axis, joint.anchor)
        damping = joint.damping or HINGE_DAMPING_PER_M * lever
        friction = joint.frictionloss or (DOOR_FRICTIONLOSS if vertical else LID_FRICTIONLOSS)
        stiffness, springref = joint.stiffness or 0.0, joint.springref or 0.0
        if not vertical and not joint.stiffness:
            friction, stiffness, springref = _balance(joint, axis, friction, mass, built)
    low, high = joint.range  # type: ignore[misc]
    body.record["joint_report"].update(
        kind=kind, kind_source=kind_source, handle="heuristic (asset_pipeline.handles)"
    )
    return {
        "name": body.name,
        "kind": kind,
        "parent": body.parent,
        "joint": {
            "name": body.record["joint_name"],
            "type": joint.type,
            "axis": [_r(v) for v in axis],
            "anchor": [_r(v) for v in joint.anchor],
            "range": [_r(low), _r(high)],
            "closed": 0.0,
            "damping": _r(damping),
            "frictionloss": _r(friction),
            "armature": _r(armature),
            "stiffness": _r(stiffness),
            "springref": _r(springref),
        },
        "mass_kg": mass,
        "visual": body.record["visual"],
        "collision": body.record["collision"],
        "handle": grasp.record(),
    }


def _balance(
    joint: JointInfo, axis: np.ndarray, friction: float, mass: float, built: _Built
) -> tuple[float, float, float]:
    """Friction loss, stiffness and spring reference of a counterbalanced horizontal hinge."""
    from asset_pipeline.procedural.articulated.links import JointDesign, balanced

    weights = np.array([c.volume for c in built.colliders])
    centres = np.array([c.points().mean(axis=0) for c in built.colliders])
    com = weights @ centres / weights.sum()
    design = JointDesign(
        "hinge",
        tuple(axis),  # type: ignore[arg-type]
        tuple(joint.anchor),  # type: ignore[arg-type]
        joint.range,  # type: ignore[arg-type]
        damping=0.0,
        frictionloss=friction,
    )
    fitted = balanced(design, mass, tuple(com))  # type: ignore[arg-type]
    return fitted.frictionloss, fitted.stiffness, fitted.springref


def _kind(body: _Body, kin: Kinematics, points: np.ndarray, asset_top: float) -> tuple[str, str]:
    joint = body.joint
    assert joint is not None
    for link in body.links:
        label = kin.labels.get(link)
        kind = _kind_word(label or "")
        if kind is not None:
            return kind, f"semantics.txt label {label!r}"
    kind = _kind_word(" ".join([*body.links, joint.name]))
    if kind is not None:
        return kind, "link or joint name"
    axis = joint.axis / np.linalg.norm(joint.axis)
    top = float(points[:, 2].max()) >= asset_top - 0.02
    if joint.type == "slide":
        if abs(float(axis[2])) < VERTICAL_COS:
            return "drawer", "horizontal slide"
        return ("lid", "vertical slide at the top") if top else ("rack", "vertical slide")
    if body.record["joint_report"]["file_range"] is None:  # an unlimited hinge: a knob
        return "flap", "continuous joint"
    if abs(float(axis[2])) >= VERTICAL_COS:
        return "door", "vertical hinge"
    if top:
        return "lid", "horizontal hinge at the top"
    return "door", "horizontal hinge"


def _kind_word(text: str) -> str | None:
    """The part kind a name's words say (``rotation_door``: door; ``slider`` is no lid)."""
    words = [w for w in re.split(r"[^a-z]+", text.lower()) if w]
    for word, kind in _KIND_WORDS:
        if any(w.startswith(word) for w in words):
            return kind
    return None


def _warn_touching(built: list[_Built], warnings: list[str]) -> None:
    """Warn about parts whose colliders' boxes overlap another body's at the closed pose (a
    part and the body it hangs on excepted: their contacts are excluded in the model)."""
    boxes = []
    for b in built:
        for collider in b.colliders:
            points = collider.points()
            boxes.append((b.body, points.min(axis=0), points.max(axis=0)))
    reported: set[tuple[str, str]] = set()
    for i, (a, alow, ahigh) in enumerate(boxes):
        for b, blow, bhigh in boxes[i + 1 :]:
            if a is b or a.name == _hangs_on(b) or b.name == _hangs_on(a):
                continue
            key = (a.name, b.name)
            if key in reported or not np.all(
                np.minimum(ahigh, bhigh) - np.maximum(alow, blow) > 0.001
            ):
                continue
            reported.add(key)
            warnings.append(
                f"{_label(a)} and {_label(b)} may touch at the closed pose (their colliders' "
                "boxes overlap): they collide when moved"
            )


def _hangs_on(body: _Body) -> str | None:
    """The name of the body a part hangs on (the carcass's is ``CARCASS``); None for it."""
    if body.joint is None:
        return None
    return body.parent if body.parent is not None else CARCASS


# --- 8. surfaces ------------------------------------------------------------------------------
def _surfaces(built: list[_Built], warnings: list[str]) -> tuple[list[dict], list[dict]]:
    """Outer surfaces of the carcass and interior surfaces (see the module docstring)."""
    triangles = np.concatenate([np.asarray(b.repaired.physics.triangles) for b in built])
    boxes = {b.body.name: np.asarray(b.repaired.physics.bounds) for b in built}
    carcass = built[0]
    own = np.asarray(carcass.repaired.physics.triangles)
    outer, interior = [], []
    joints = {b.body.name: b.body for b in built[1:]}
    for surface in support_surfaces(carcass.repaired.physics):
        record = _surface(surface)
        clear = _clearance(surface, triangles)
        covered = math.isfinite(_clearance(surface, own))
        polygon = np.asarray(surface.polygon)
        (_x0, y0), (x1, y1) = polygon.min(axis=0), polygon.max(axis=0)
        top = surface.height + (min(clear, 1.0) if math.isfinite(clear) else 1.0)
        front = [
            name
            for name, body in joints.items()
            if body.parent is None
            and boxes[name][0, 1] < y1
            and boxes[name][1, 1] > y0
            and boxes[name][0, 2] < top
            and boxes[name][1, 2] > surface.height
            and boxes[name][1, 0] >= x1 - FRONT_MARGIN_M
        ]
        if not (covered and front):
            outer.append(record)
            continue
        if clear < MIN_CLEARANCE_M:
            warnings.append(
                f"interior surface at z = {surface.height:.3f} m left out: {clear:.3f} m free above"
            )
            continue
        behind = [_joint_name(joints[name]) for name in front]
        interior.append(
            record | {"part": None, "behind": behind, "clearance_m": _r(min(clear, 10.0))}
        )
    for b in built[1:]:
        chain = [_joint_name(b.body)]
        parent = b.body.parent
        while parent is not None:
            chain.insert(0, _joint_name(joints[parent]))
            parent = joints[parent].parent
        for surface in support_surfaces(b.repaired.physics):
            clear = _clearance(surface, triangles)
            if not math.isfinite(clear):
                warnings.append(
                    f"{_label(b.body)}: its upward surface at z = {surface.height:.3f} m is "
                    "outside (nothing above it when closed): not recorded"
                )
                continue
            if clear < MIN_CLEARANCE_M:
                continue
            interior.append(
                _surface(surface)
                | {"part": b.body.name, "behind": chain, "clearance_m": _r(min(clear, 10.0))}
            )
    interior.sort(key=lambda s: (s["part"] or "", s["height"], s["polygon"]))
    return outer, interior


def _joint_name(body: _Body) -> str:
    """The name the part's joint gets in the metadata (as :func:`_part_record` makes it)."""
    return body.record["joint_name"]


def _surface(surface: Any) -> dict:
    return {
        "height": surface.height,
        "polygon": [list(p) for p in surface.polygon],
        "area_m2": surface.area,
    }


def _clearance(surface: Any, triangles: np.ndarray, samples: int = 15) -> float:
    """The smallest free height above ``surface`` to any of ``triangles`` (inf: none above)."""
    polygon = np.asarray(surface.polygon)
    (x0, y0), (x1, y1) = polygon.min(axis=0), polygon.max(axis=0)
    lo, hi = triangles[:, :, :2].min(axis=1), triangles[:, :, :2].max(axis=1)
    near = (hi[:, 0] >= x0) & (lo[:, 0] <= x1) & (hi[:, 1] >= y0) & (lo[:, 1] <= y1)
    tri = triangles[near]
    if len(tri) == 0:
        return math.inf
    from shapely import contains_xy
    from shapely.geometry import Polygon

    gx, gy = np.meshgrid(np.linspace(x0, x1, samples), np.linspace(y0, y1, samples))
    points = np.column_stack([gx.ravel(), gy.ravel()])
    shape = Polygon(polygon).buffer(1e-6)
    points = points[contains_xy(shape, points[:, 0], points[:, 1])]
    if len(points) == 0:
        return math.inf
    cross = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nz = cross[:, 2] / np.maximum(np.linalg.norm(cross, axis=1), 1e-12)
    hit_z, _ = _first_hits(points, tri, nz, surface.height + 0.001)
    return float(hit_z.min() - surface.height)


def _partnet_category(model_cat: str) -> str:
    if model_cat in PARTNET_CATEGORIES:
        return PARTNET_CATEGORIES[model_cat]
    return re.sub(r"(?<!^)(?=[A-Z])", "_", model_cat).lower()


def _r(value: float) -> float:
    value = float(value)
    return 0.0 if abs(value) < 1e-12 else round(value, 9)
