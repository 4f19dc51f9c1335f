"""A dm_control composer Arena for a holomj scene folder.

``HolomjArena(folder)`` loads ``folder/scene.xml`` with ``mjcf.from_path(...,
escape_separators=True)`` (holomj's names hold ``/``). Robots and props attach as in any arena;
:meth:`HolomjArena.robot_spot` finds a free floor spot for an entity of a given footprint radius
(the same occupancy map and rules as ``--robot``), :meth:`HolomjArena.attach_at` attaches
an entity there, turned to face the room, and :meth:`HolomjArena.find` finds elements by their
holomj names::

    from dm_control import composer
    from dm_control.entities.manipulators.kinova import jaco_arm
    arena = HolomjArena("out/house")
    arm = jaco_arm.JacoArm()
    arena.attach_at(arm, arena.robot_spot(radius=0.4))
    env = composer.Environment(MyTask(arena, arm))
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from dm_control import composer, mjcf
from dm_control.mjcf import constants

from holomj.errors import FormatError
from holomj.file_names import SCENE_XML
from holomj.formats.objects_json import OBJECTS_JSON
from holomj.jobs.folder import read_robot, read_scene
from holomj.mjcf.geometry import yaw_quat
from holomj.mjcf.loading import load_model_file
from holomj.robots.occupancy import build_floor_grid
from holomj.robots.placement import DEFAULT_CLEARANCE_M, Spot, choose_spot
from holomj.robots.reach import compute_reach
from holomj.seeds import seed_rng
from holomj.spec.base import read_json
from holomj.spec.robot import Footprint, RobotRecord
from holomj.spec.scene import SceneSpec


def escape_name(name: str) -> str:
    """A holomj element name as ``mjcf.from_path(..., escape_separators=True)`` stores it."""
    return name.replace(
        constants.PREFIX_SEPARATOR_ESCAPE, constants.PREFIX_SEPARATOR_ESCAPE * 2
    ).replace(constants.PREFIX_SEPARATOR, constants.PREFIX_SEPARATOR_ESCAPE)


class HolomjArena(composer.Arena):
    """The scene of a holomj folder as a composer Arena (robot included when it has one)."""

    def _build(self, folder: Path | str, name: str | None = None) -> None:
        """Load ``folder/scene.xml``; ``name`` overrides the model name."""
        folder = Path(folder)
        xml = folder / SCENE_XML
        if not xml.is_file():
            raise FormatError(
                "no scene.xml", where=str(folder), fix="pass a folder written by holomj"
            )
        try:
            self._mjcf_root = mjcf.from_path(str(xml), escape_separators=True)
        except (ValueError, KeyError, TypeError, AttributeError) as err:
            raise FormatError(
                f"dm_control cannot parse it: {' '.join(str(err).split())}", where=str(xml)
            ) from None
        if name:
            self._mjcf_root.model = name
        self._folder = folder
        self._scene: SceneSpec | None = None

    def find(self, namespace: str, name: str) -> Any:
        """The MJCF element of holomj name ``name`` (e.g. ``find("body", "sofa_1/body")``),
        or None; holomj's ``/`` separators are escaped as dm_control stores them."""
        return self._mjcf_root.find(namespace, escape_name(name))

    @property
    def folder(self) -> Path:
        """The holomj folder this arena was loaded from."""
        return self._folder

    @property
    def scene(self) -> SceneSpec:
        """The folder's ``scene.json``."""
        if self._scene is None:
            self._scene = read_scene(self._folder)
        return self._scene

    @property
    def robot_record(self) -> RobotRecord | None:
        """The folder's ``robot.json`` (a robot holomj attached), or None."""
        return read_robot(self._folder)

    def robot_spot(
        self,
        radius: float,
        *,
        seed: int = 0,
        clearance: float = DEFAULT_CLEARANCE_M,
        room: str | None = None,
        front_deg: float = 0.0,
    ) -> Spot:
        """A free floor spot, reachable from the entrance, for an entity whose footprint fits in
        a disc of ``radius`` metres; its yaw turns ``front_deg`` (the entity's reach direction)
        towards the room's furniture."""
        model = load_model_file(self._folder / SCENE_XML)
        grid = build_floor_grid(model, self.scene)
        reach = compute_reach(grid, self.scene)
        footprint = Footprint(
            radius_m=radius,
            height_m=1.0,
            front_deg=front_deg,
            polygon=[(radius, 0.0), (0.0, radius), (-radius, 0.0)],
        )
        return choose_spot(
            grid,
            reach,
            self.scene,
            footprint,
            seed_rng(seed),
            clearance=clearance,
            room=room,
        )

    def articulations(self) -> list[dict[str, Any]]:
        """The joints of the scene's moving parts (doors, drawers, lids of articulated objects),
        as ``objects.json`` lists them (name, type, axis, range, closed value, the body to grasp
        and the handle's pose), each with its ``object`` id and its dm_control elements:
        ``joint_element``, ``body_element`` and ``handle_element`` (the handle site, or None),
        ready for ``physics.bind``. Empty when the scene has none."""
        path = self._folder / OBJECTS_JSON
        if not path.is_file():
            return []
        found = []
        for obj in read_json(path).get("objects", []):
            for joint in obj.get("joints", []):
                handle = joint.get("handle")
                found.append(
                    {
                        **joint,
                        "object": obj["id"],
                        "joint_element": self.find("joint", joint["name"]),
                        "body_element": self.find("body", joint["body"]),
                        "handle_element": self.find("site", handle["site"]) if handle else None,
                    }
                )
        return found

    def attach_at(self, entity: composer.Entity, spot: Spot) -> Any:
        """Attach ``entity`` (fixed base) at ``spot``; returns its attachment frame."""
        frame = self.attach(entity)
        frame.pos = [spot.x, spot.y, 0.0]
        frame.quat = list(yaw_quat(math.radians(spot.yaw_deg)))
        return frame
