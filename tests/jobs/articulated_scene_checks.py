"""The issue's open/close checks, run on every moving part listed in a scene folder's
``objects.json`` against its exported ``scene.xml`` (what :mod:`tests.jobs.
test_articulated_scenes` runs on generated kitchens and bedrooms).

For one part, in a fresh state of the whole scene: a 30 N pull on its handle site along the
opening direction for 1.5 s opens a door at least 20 degrees and a drawer (or rack) at least
10 cm; the same force reversed for 1.5 s closes it again, no contact of the part deeper than
1 mm on the way (with anything but what rests inside its object: a cup on a rack rides along
and sags into it under the push as a resting object does; its deepest contact is reported
apart, ``contents_m``); it ends within 1 degree / 2 mm of closed and stays there for 2 s left
alone.
Before any part is touched, the whole scene is left alone 2 s: no part moves more than 0.5
degree / 1 mm. A part whose parent part must open first (a dishwasher rack behind its door) gets
that part opened to its limit first.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from tests.asset_pipeline.articulated_helpers import HINGE, simulate, value, warnings_of

OPEN_DOOR_RAD = math.radians(20.0)
OPEN_DRAWER_M = 0.10
DEEPEST_M = 0.001
PULL_S = 1.5
REST_S = 2.0


@dataclass(frozen=True)
class PartCheck:
    """What one part did."""

    joint: str
    kind: str
    opened: float  # radians or metres after the pull
    deepest_m: float  # deepest contact of the part while it was pushed closed
    contents_m: float  # deepest contact of the part with what rests in its object meanwhile
    closed: float  # value after the push and a short rest
    after_rest: float  # value after 2 s more left alone
    warnings: dict[str, int]

    @property
    def hinge(self) -> bool:
        return self.kind == "hinge"

    @property
    def problems(self) -> list[str]:
        """What failed, in words (empty: it passed)."""
        found = []
        need = OPEN_DOOR_RAD if self.hinge else OPEN_DRAWER_M
        unit = "rad" if self.hinge else "m"
        if self.opened < need:
            found.append(f"opened only {self.opened:.3f} {unit} (needs {need:.3f})")
        if self.deepest_m > DEEPEST_M:
            found.append(f"closed with a contact {self.deepest_m * 1000:.2f} mm deep")
        tol = math.radians(1.0) if self.hinge else 0.002
        if abs(self.closed) > tol:
            found.append(f"ended at {self.closed:.4f} {unit} after the push")
        if abs(self.after_rest) > tol:
            found.append(f"drifted to {self.after_rest:.4f} {unit} left alone 2 s")
        if self.warnings:
            found.append(f"MuJoCo warnings {self.warnings}")
        return found


def listed_joints(folder: Path) -> list[dict]:
    """Every moving part's joint record in the folder's ``objects.json``."""
    data = json.loads((folder / "objects.json").read_text())
    return [j for o in data["objects"] for j in (o.get("joints") or []) if j.get("part")]


def contents(folder: Path, model: mujoco.MjModel) -> dict[str, set[int]]:
    """The bodies of the small objects resting on or in each object (``support`` in
    ``scene.json``), by object id."""
    scene = json.loads((folder / "scene.json").read_text())
    found: dict[str, set[int]] = {}
    for obj in scene["objects"]:
        if obj.get("support"):
            found.setdefault(obj["support"], set()).add(model.body(f"{obj['id']}/body").id)
    return found


def _part_deepest(
    model: mujoco.MjModel, data: mujoco.MjData, body: int, inside: set[int]
) -> tuple[float, float]:
    """(deepest contact of ``body`` with anything but ``inside``, with ``inside``)."""
    deepest, contents_deepest = 0.0, 0.0
    for k in range(data.ncon):
        contact = data.contact[k]
        b1, b2 = model.geom_bodyid[contact.geom[0]], model.geom_bodyid[contact.geom[1]]
        if body in (b1, b2):
            other = b2 if b1 == body else b1
            if other in inside:
                contents_deepest = max(contents_deepest, -float(contact.dist))
            else:
                deepest = max(deepest, -float(contact.dist))
    return deepest, contents_deepest


def _pull(
    model: mujoco.MjModel,
    data: mujoco.MjData,
    joint: int,
    site: int,
    sign: float,
    seconds: float,
    inside: frozenset[int] | set[int] = frozenset(),
) -> tuple[float, float]:
    """Pull (sign +1) or push (-1) the handle ``site`` of ``joint``'s part for ``seconds``;
    returns the deepest contact of that part seen meanwhile (with anything but the bodies
    ``inside``, and with them)."""
    body = int(model.jnt_bodyid[joint])
    deepest, contents_deepest = 0.0, 0.0
    for _ in range(round(seconds / model.opt.timestep)):
        data.xfrc_applied[body] = 0.0
        point = data.site_xpos[site]
        if int(model.jnt_type[joint]) == HINGE:
            direction = np.cross(data.xaxis[joint], point - data.xanchor[joint])
            direction /= np.linalg.norm(direction)
        else:
            direction = data.xaxis[joint].copy()
        force = sign * 30.0 * direction
        data.xfrc_applied[body, :3] = force
        data.xfrc_applied[body, 3:] = np.cross(point - data.xipos[body], force)
        mujoco.mj_step(model, data)
        found, found_inside = _part_deepest(model, data, body, set(inside))
        deepest = max(deepest, found)
        contents_deepest = max(contents_deepest, found_inside)
    data.xfrc_applied[body] = 0.0
    return deepest, contents_deepest


def _fresh(model: mujoco.MjModel) -> mujoco.MjData:
    data = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    return data


def left_alone(model: mujoco.MjModel, joints: list[dict]) -> dict[str, float]:
    """How far each listed joint moves in 2 s with nothing touching it."""
    data = _fresh(model)
    ids = [model.joint(j["name"]).id for j in joints]
    start = [value(model, data, j) for j in ids]
    simulate(model, data, REST_S)
    return {
        j["name"]: abs(value(model, data, i) - s)
        for j, i, s in zip(joints, ids, start, strict=True)
    }


def check_part(
    model: mujoco.MjModel,
    record: dict,
    records: list[dict],
    inside: set[int] | frozenset[int] = frozenset(),
) -> PartCheck:
    """The open/close check of the part of one ``objects.json`` joint record; ``inside``: the
    bodies resting in its object (:func:`contents`)."""
    joint = model.joint(record["name"]).id
    site = model.site(record["handle"]["site"]).id
    data = _fresh(model)
    parent = int(model.body_parentid[int(model.jnt_bodyid[joint])])
    for other in records:  # open what the part hangs behind (a dishwasher rack's door)
        if other is record or not other["name"].startswith(record["name"].split("/")[0] + "/"):
            continue
        if record["kind"] == "rack" and other["kind"] == "door":
            j = model.joint(other["name"]).id
            if int(model.jnt_bodyid[j]) != parent:
                data.qpos[model.jnt_qposadr[j]] = model.jnt_range[j][1]
    mujoco.mj_forward(model, data)
    simulate(model, data, 0.3)
    _pull(model, data, joint, site, +1.0, PULL_S, inside)
    opened = value(model, data, joint)
    deepest, contents_deepest = _pull(model, data, joint, site, -1.0, PULL_S, inside)
    simulate(model, data, 0.3)
    closed = value(model, data, joint)
    simulate(model, data, REST_S)
    return PartCheck(
        joint=record["name"],
        kind="hinge" if int(model.jnt_type[joint]) == HINGE else "slide",
        opened=opened,
        deepest_m=deepest,
        contents_m=contents_deepest,
        closed=closed,
        after_rest=value(model, data, joint),
        warnings=warnings_of(data),
    )
