"""The bodies of an articulated file (steps 1 to 3 of :mod:`asset_pipeline.articulated_import`):
the carcass and one body per moving joint, each part at its closed pose, all normalised together
into the asset frame."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from asset_pipeline.kinematics import JointInfo, Kinematics, joint_motion, transformed
from asset_pipeline.load import MeshPart
from asset_pipeline.normalise import _UP, Front, Normalisation, UpAxis, normalise
from asset_pipeline.repair import Repaired
from holomj.errors import FormatError

CARCASS = ""


RESERVED_PARTS = frozenset({"body"})  # holomj.mjcf.names: <object>/body is the carcass


RESERVED_JOINTS = frozenset({"freejoint"})


@dataclass
class Body:
    """The carcass or one moving part: links, joint (None: carcass), parent part, geometry."""

    name: str
    links: list[str]
    joint: JointInfo | None = None
    parent: str | None = None
    parts: list[MeshPart] = field(default_factory=list)
    merged_joints: list[str] = field(default_factory=list)
    record: dict = field(default_factory=dict)

    @property
    def moving_joint(self) -> JointInfo:
        """The joint a part moves on; a ValueError for the carcass."""
        if self.joint is None:
            raise ValueError(f"body {self.name!r} is the carcass: it has no joint")
        return self.joint


@dataclass
class Built:
    """A body after repair and decomposition."""

    body: Body
    repaired: Repaired
    colliders: list
    decomposition: Any
    quality: dict


def split_bodies(kin: Kinematics, where: str, warnings: list[str]) -> tuple[Body, list[Body]]:
    children = {j.child for j in kin.joints}
    roots = [name for name in kin.links if name not in children]
    carcass = Body(CARCASS, list(roots))
    body_of = dict.fromkeys(roots, CARCASS)
    bodies: dict[str, Body] = {CARCASS: carcass}
    part_names: set[str] = set(RESERVED_PARTS)
    for joint in kin.joints:
        owner = body_of[joint.parent]
        if joint.type == "fixed":
            body_of[joint.child] = owner
            bodies[owner].links.append(joint.child)
            continue
        name = _unique(_identifier(joint.child, "part"), part_names)
        body_of[joint.child] = name
        bodies[name] = Body(name, [joint.child], joint, None if owner == CARCASS else owner)
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
        body.record["joint_name"] = _unique(
            _identifier(body.moving_joint.name, "joint"), joint_names
        )
    return carcass, parts


def _absorb_children(body: Body, bodies: dict[str, Body], warnings: list[str]) -> None:
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


def _descendants(body: Body, parts: list[Body]) -> list[Body]:
    found, frontier = [], [body.name]
    while frontier:
        name = frontier.pop()
        for other in parts:
            if other.parent == name:
                found.append(other)
                frontier.append(other.name)
    return found


def close_parts(parts: list[Body], warnings: list[str]) -> None:
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


def normalised_bodies(
    bodies: list[Body],
    where: str,
    up_axis: UpAxis,
    front: Front,
    size: tuple[float, float, float] | None,
) -> Normalisation:
    """Normalise all bodies' geometry together (one frame for the whole asset) and move the
    parts' joints into it."""
    counts = [len(b.parts) for b in bodies]
    flat, frame = normalise([p for b in bodies for p in b.parts], where, up_axis, front, size)
    start = 0
    for body, count in zip(bodies, counts, strict=True):
        body.parts, start = flat[start : start + count], start + count
        if body.joint is not None:
            body.joint = _moved_joint(body.joint, frame)
    return frame


def opening_front(parts: list[Body], up_axis: UpAxis) -> Front:
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


def _moved_joint(joint: JointInfo, frame: Normalisation) -> JointInfo:
    """``joint`` in the asset frame (``frame``: the Normalisation applied to the meshes)."""
    rot, scale = frame.rotation, frame.scale
    low, high = joint.limits()
    if joint.type == "slide":
        low, high = low * scale, high * scale
    return replace(
        joint,
        axis=rot @ joint.axis,
        anchor=scale * (rot @ joint.anchor) + frame.translation,
        range=(low, high),
    )


def body_label(body: Body) -> str:
    return f"part {body.name!r} (link {body.links[0]!r})" if body.name else "the fixed part"


def joint_name(body: Body) -> str:
    """The name the part's joint gets in the metadata (as :func:`part_record` makes it)."""
    return body.record["joint_name"]


def rounded(value: float) -> float:
    value = float(value)
    return 0.0 if abs(value) < 1e-12 else round(value, 9)
