"""A scene folder as a Python object: ``holomj.Scene.load(folder)``.

Reads what the folder holds (``scene.json``, its asset library, and the reports when present)
and offers the objects with their category, room and pose, the rooms, the validation report and
the plan; ``validate()``, ``render()`` and ``model()`` run the jobs on the folder.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Any, TypeVar

from holomj.errors import InputError, closest_names
from holomj.file_names import PLAN_JSON, REPORT_JSON, SCENE_XML
from holomj.jobs.folder import (
    open_library,
    read_json_report,
    read_robot,
    read_scene,
    require_scene_folder,
)
from holomj.library.store import AssetLibrary
from holomj.spec.base import validate_model
from holomj.spec.edit import EditReport
from holomj.spec.plan import ScenePlan
from holomj.spec.report import StabilityReport
from holomj.spec.robot import RobotRecord
from holomj.spec.scene import Room, SceneObject, SceneSpec


@dataclass(frozen=True)
class Pose:
    """Where an object's origin (the centre of its footprint, at its bottom) is, and how it is
    turned: ``position`` in metres, ``quat`` (w, x, y, z), ``yaw_deg`` about +Z."""

    position: tuple[float, float, float]
    quat: tuple[float, float, float, float]
    yaw_deg: float


@dataclass(frozen=True)
class TaskObjectInfo:
    """One object of a scene, as a robot-learning task needs it."""

    id: str
    category: str
    asset: str
    room: str | None
    pose: Pose
    static: bool
    support: str | None
    size: tuple[float, float, float]  # extent x, y, z in metres, scale applied


def object_pose(obj: SceneObject) -> Pose:
    """The pose of a scene object (its ``quat`` when given, else its yaw)."""
    if obj.quat is not None:
        w, x, y, z = obj.quat
        norm = math.sqrt(w * w + x * x + y * y + z * z)
        quat = (w / norm, x / norm, y / norm, z / norm)
        yaw = math.degrees(
            math.atan2(
                2 * (quat[0] * quat[3] + quat[1] * quat[2]), 1 - 2 * (quat[2] ** 2 + quat[3] ** 2)
            )
        )
    else:
        half = math.radians(obj.yaw_deg) / 2
        quat, yaw = (math.cos(half), 0.0, 0.0, math.sin(half)), obj.yaw_deg
    px, py, pz = obj.position
    return Pose((px, py, pz), quat, round(yaw, 6))


_Scene = TypeVar("_Scene", bound="Scene")


class Scene:
    """A holomj scene folder, loaded (re-exported as ``holomj.Scene``): ``Scene.load(folder)``
    or ``Scene.open(folder)``; ``.objects``, ``.rooms``, ``.report``, ``.model()``, and
    ``.edit(ops)``.

    Raises :class:`~holomj.errors.InputError` for a folder that is not a holomj scene and
    :class:`~holomj.errors.FormatError` for one whose files cannot be read.
    """

    def __init__(self, folder: Path, spec: SceneSpec, library: AssetLibrary) -> None:
        self.folder = folder
        self.spec = spec
        self.library = library

    @classmethod
    def load(cls: type[_Scene], folder: Path | str) -> _Scene:
        """Load the scene folder ``folder`` (written by generate, compile, populate, ...)."""
        folder = require_scene_folder(Path(folder), "holomj generate' or 'holomj compile")
        return cls(folder, read_scene(folder), open_library(folder))

    @classmethod
    def open(cls: type[_Scene], folder: Path | str) -> _Scene:
        """Load the scene folder ``folder`` (as :meth:`load`)."""
        return cls.load(folder)

    def __repr__(self) -> str:
        return (
            f"Scene({str(self.folder)!r}: {len(self.spec.rooms)} rooms, "
            f"{len(self.spec.objects)} objects)"
        )

    @property
    def name(self) -> str:
        """The scene's name."""
        return self.spec.name

    @property
    def rooms(self) -> list[Room]:
        """The rooms (id, type, polygon, materials)."""
        return list(self.spec.rooms)

    @cached_property
    def objects(self) -> list[TaskObjectInfo]:
        """Every object, in the scene's order."""
        return [self._info(obj) for obj in self.spec.objects]

    def object(self, object_id: str) -> TaskObjectInfo:
        """The object ``object_id``; an error naming close ids when there is none."""
        for info in self.objects:
            if info.id == object_id:
                return info
        near = closest_names(object_id, [o.id for o in self.objects])
        raise InputError(
            f"no object {object_id!r}",
            where=str(self.folder),
            fix=f"did you mean {near}?" if near else None,
        )

    def in_room(self, room_id: str) -> list[TaskObjectInfo]:
        """The objects of one room."""
        return [o for o in self.objects if o.room == room_id]

    @property
    def report(self) -> StabilityReport | None:
        """The folder's validation report (``report.json``), or None."""
        data = read_json_report(self.folder, REPORT_JSON)
        path = str(self.folder / REPORT_JSON)
        return None if data is None else validate_model(StabilityReport, data, path)

    @property
    def plan(self) -> ScenePlan | None:
        """The plan ``holomj generate`` made (``plan.json``), or None."""
        data = read_json_report(self.folder, PLAN_JSON)
        path = str(self.folder / PLAN_JSON)
        return None if data is None else validate_model(ScenePlan, data, path)

    @property
    def robot(self) -> RobotRecord | None:
        """The robot the folder carries, or None."""
        return read_robot(self.folder)

    @property
    def xml_path(self) -> Path:
        """The folder's ``scene.xml``."""
        return self.folder / SCENE_XML

    def model(self) -> Any:
        """The exported ``scene.xml`` as a ``mujoco.MjModel``."""
        from holomj.mjcf.loading import load_model_file

        return load_model_file(self.xml_path)

    def validate(self, **options: Any) -> StabilityReport:
        """:func:`holomj.validate` on this folder (keywords as there)."""
        from holomj.jobs.validate import validate

        return validate(self.folder, **options)

    def edit(
        self,
        ops: Path | str | Sequence[Any],
        out: Path | str | None = None,
        *,
        seed: int = 0,
        library: Path | str | AssetLibrary | None = None,
        overwrite: bool = False,
        validate: bool = True,
    ) -> EditReport:
        """``holomj edit``: apply edit operations (a JSON file, or a list of operations as
        dicts or :mod:`holomj.spec.edit` models) and write the result into ``out`` (a new
        folder), or back into this folder, which this object then shows.

        Returns the :class:`~holomj.spec.edit.EditReport` (``.ok``, ``.operations`` with each
        one's ``status`` and ``reason``, ``.added``, ``.removed``, ``.moved``,
        ``.validation``). Raises :class:`~holomj.errors.InputError` for a malformed operations
        list (nothing is written) and :class:`~holomj.errors.OutputExistsError` when ``out``
        exists (without ``overwrite``); refused operations are in the report, not raised.
        """
        from holomj.jobs.edit import apply_edits
        from holomj.jobs.library import resolve_library

        report = apply_edits(
            self.folder,
            ops,
            out,
            seed=seed,
            library_path=resolve_library(library),
            overwrite=overwrite,
            validate=validate,
        )
        if out is None or Path(out).resolve() == Path(self.folder).resolve():
            fresh = type(self).load(self.folder)
            self.spec, self.library = fresh.spec, fresh.library
            self.__dict__.pop("objects", None)  # the cached object list
        return report

    def _info(self, obj: SceneObject) -> TaskObjectInfo:
        meta = self.library.get(obj.asset).meta if obj.asset in self.library else None
        sx, sy, sz = obj.scale3
        size = (meta.size[0] * sx, meta.size[1] * sy, meta.size[2] * sz) if meta else (sx, sy, sz)
        return TaskObjectInfo(
            id=obj.id,
            category=meta.category if meta is not None else obj.asset,
            asset=obj.asset,
            room=obj.room,
            pose=object_pose(obj),
            static=obj.static,
            support=obj.support,
            size=(round(size[0], 6), round(size[1], 6), round(size[2], 6)),
        )
