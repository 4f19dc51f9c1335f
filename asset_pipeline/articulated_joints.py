"""The joints, handles and kinds of an articulated asset's parts (steps 6 and 7 of
:mod:`asset_pipeline.articulated_import`), and the warning about parts that touch."""

from __future__ import annotations

import math
import re

import numpy as np

from asset_pipeline.articulated_bodies import (
    CARCASS,
    Body,
    Built,
    body_label,
    rounded,
)
from asset_pipeline.handles import derive_grasp, lever_m
from asset_pipeline.kinematics import JointInfo, Kinematics

VERTICAL_COS = math.cos(math.radians(20.0))


# holomj's defaults for furniture (asset_pipeline.procedural.articulated.links).
HINGE_DAMPING_PER_M = 20.0


DOOR_FRICTIONLOSS = 0.6


DRAWER_DAMPING = 60.0


DRAWER_FRICTIONLOSS = 3.0


LID_FRICTIONLOSS = 0.5


ARMATURE = 0.01


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


def part_record(built: Built, mass: float, kin: Kinematics, asset_top: float) -> dict:
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
    low, high = joint.limits()
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
            "axis": [rounded(v) for v in axis],
            "anchor": [rounded(v) for v in joint.anchor],
            "range": [rounded(low), rounded(high)],
            "closed": 0.0,
            "damping": rounded(damping),
            "frictionloss": rounded(friction),
            "armature": rounded(armature),
            "stiffness": rounded(stiffness),
            "springref": rounded(springref),
        },
        "mass_kg": mass,
        "visual": body.record["visual"],
        "collision": body.record["collision"],
        "handle": grasp.record(),
    }


def _balance(
    joint: JointInfo, axis: np.ndarray, friction: float, mass: float, built: Built
) -> tuple[float, float, float]:
    """Friction loss, stiffness and spring reference of a counterbalanced horizontal hinge."""
    from asset_pipeline.procedural.articulated.links import JointDesign, balanced

    weights = np.array([c.volume for c in built.colliders])
    centres = np.array([c.points().mean(axis=0) for c in built.colliders])
    com = weights @ centres / weights.sum()
    design = JointDesign(
        "hinge",
        tuple(axis),
        tuple(joint.anchor),
        joint.limits(),
        damping=0.0,
        frictionloss=friction,
    )
    fitted = balanced(design, mass, tuple(com))
    return fitted.frictionloss, fitted.stiffness, fitted.springref


def _kind(body: Body, kin: Kinematics, points: np.ndarray, asset_top: float) -> tuple[str, str]:
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


def warn_touching(built: list[Built], warnings: list[str]) -> None:
    """Warn about parts whose colliders' boxes overlap another body's at the closed pose (a
    part and the body it hangs on excepted: their contacts are excluded in the model)."""
    boxes = []
    for done in built:
        for collider in done.colliders:
            points = collider.points()
            boxes.append((done.body, points.min(axis=0), points.max(axis=0)))
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
                f"{body_label(a)} and {body_label(b)} may touch at the closed pose (their "
                "colliders' boxes overlap): they collide when moved"
            )


def _hangs_on(body: Body) -> str | None:
    """The name of the body a part hangs on (the carcass's is ``CARCASS``); None for it."""
    if body.joint is None:
        return None
    return body.parent if body.parent is not None else CARCASS
