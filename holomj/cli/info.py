"""``holomj info OUT``: rooms, objects, bodies, geoms and mass of a scene folder (the job:
:mod:`holomj.jobs.info`)."""

from __future__ import annotations

from rich.table import Table

from holomj.cli.options import FolderArg, JsonOption
from holomj.cli.output import emit_json, guard, out_console


def info_command(folder: FolderArg, as_json: JsonOption = False) -> None:
    """Rooms, objects, bodies, geoms and mass of an exported scene."""
    from holomj.jobs.info import folder_summary

    summary = guard(lambda: folder_summary(folder))
    if as_json:
        emit_json(summary.to_dict())
        return
    scene, model = summary.scene, summary.model
    table = Table(title=f"{scene.name} ({summary.folder})")
    table.add_column("room")
    table.add_column("type")
    table.add_column("area m²", justify="right")
    for room in scene.rooms:
        table.add_row(room.id, room.type, f"{room.area_m2:.2f}")
    out_console.print(table)
    out_console.print(
        f"walls {scene.walls}, doors {scene.doors}, windows {scene.windows}, "
        f"objects {scene.objects} ({scene.dynamic_objects} dynamic, "
        f"{scene.static_objects} static), lights {summary.lights}"
    )
    out_console.print(
        f"bodies {model.bodies}, geoms {model.geoms}, joints {model.joints} "
        f"({model.free_joints} free, {model.hinges} hinges), meshes {model.meshes}, "
        f"mass {model.total_mass_kg} kg"
    )
