"""A planned house composed into a scene: the shell (rooms, doors, windows, materials) and every
room furnished, the plan grown where a room's furniture did not fit.

A room whose size the request left open grows (up to ``MAX_GROWTH`` times by ``GROWTH`` in area)
and the house is laid out again when its defining furniture does not fit even with its windows
moved, or when its furniture cuts off free floor (less than ``REGROW_SHARE`` reachable).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from holomj.compose.house_shell import HouseShell, MaterialPicker, build_shell
from holomj.compose.room_assets import RoomAssets
from holomj.compose.room_context import RoomContext, RoomFurniture
from holomj.compose.room_furnishing import furnish_room
from holomj.library.store import AssetLibrary
from holomj.spec.materials import BUILTIN_MATERIALS
from holomj.spec.plan import PlanRoom, ScenePlan
from holomj.spec.scene import SceneSpec
from holomj.spec.walls import derive_walls

GROWTH = 1.25  # a room grows by this factor in area when its defining furniture does not fit
MAX_GROWTH = 2
# ... or when less than this share of its free floor is reachable (the layout's own measure,
# holomj.layout.open_pockets, stricter than the evaluator's: a 0.17 m robot's floor reached
# through passages a 0.25 m one fits)
REGROW_SHARE = 0.95

Note = Callable[[str], None]  # one line of the layout's log


@dataclass(frozen=True)
class ComposedHouse:
    """The plan as laid out (grown rooms included), its shell, every room's furnishing and the
    scene they make (before small objects)."""

    plan: ScenePlan
    shell: HouseShell
    furnished: tuple[RoomFurniture, ...]
    scene: SceneSpec


def scene_name(prompt: str) -> str:
    """A short name for the scene from its prompt."""
    words = re.findall(r"[a-z0-9]+", prompt.lower())[:8]
    return "_".join(words)[:64] or "scene"


def compose_house(
    prompt: str,
    plan: ScenePlan,
    assets: Mapping[str, RoomAssets],
    library: AssetLibrary,
    seed: int,
    pick_material: MaterialPicker,
    *,
    layout_time_s: float,
    note: Note,
) -> ComposedHouse:
    """Lay out ``plan`` with each room's retrieved ``assets`` (room id -> assets), growing rooms
    as the module docstring says; ``note`` gets one line per event (warnings, plan changes,
    each room's outcome)."""
    grown: list[str] = []
    for _ in range(MAX_GROWTH + 1):
        shell = build_shell(plan, seed, pick_material)
        for warning in shell.warnings:
            note(f"warning: {warning}")
        furnished = _furnish_rooms(plan, shell, assets, library, seed, layout_time_s)
        short = {
            room.id: why
            for room, done in zip(plan.rooms, furnished)
            if room.size is None and room.area_m2 is not None and (why := why_grow(room, done))
        }
        if not short or len(grown) >= MAX_GROWTH:
            break
        plan, change = grow(plan, short)
        grown.append(change)
        note(f"changed the plan: {change}; laying out again")
    if grown:
        furnished[0].changes[:0] = grown
    for done in furnished:
        _note_room(done, note)
    # each room's windows as its furnishing left them (a window may have moved)
    order = {w.id: i for i, w in enumerate(shell.windows)}
    windows = sorted((w for r in furnished for w in r.windows), key=lambda w: order[w.id])
    scene = SceneSpec(
        name=scene_name(prompt),
        wall_height=plan.wall_height,
        rooms=shell.rooms,
        doors=shell.doors,
        windows=windows,
        objects=[o for r in furnished for o in r.objects],
        materials={n: m for n, m in shell.materials.items() if n not in BUILTIN_MATERIALS},
        source=f"holomj generate (seed {seed}): {prompt}",
    )
    return ComposedHouse(plan, shell, tuple(furnished), scene)


def _furnish_rooms(
    plan: ScenePlan,
    shell: HouseShell,
    assets: Mapping[str, RoomAssets],
    library: AssetLibrary,
    seed: int,
    layout_time_s: float,
) -> list[RoomFurniture]:
    """Every room of ``plan`` furnished in ``shell``."""
    context = RoomContext(
        walls=derive_walls(shell.rooms),
        doors=shell.doors,
        windows=shell.windows,
        wall_height=plan.wall_height,
        wall_thickness=SceneSpec.model_fields["wall_thickness"].default,
    )
    rooms = {r.id: r for r in shell.rooms}
    return [
        furnish_room(
            plan_room,
            rooms[plan_room.id],
            context,
            assets[plan_room.id],
            library,
            seed,
            time_limit_s=layout_time_s,
        )
        for plan_room in plan.rooms
    ]


def _note_room(done: RoomFurniture, note: Note) -> None:
    """The log lines of one furnished room: its plan changes, its outcome, what was left out."""
    for change in done.changes:
        note(f"changed the plan: {change}")
    lay = done.layout
    note(
        f"{done.room_id}: {len(done.objects)} object(s) placed, "
        f"{len(done.unplaced)} not, constraints "
        f"{lay.get('constraints_satisfied', 0)}/{lay.get('constraints_total', 0)} "
        f"({lay.get('solver', '-')}, {lay.get('seconds', 0):.2f} s)"
    )
    for item in done.unplaced:
        note(f"{done.room_id}: not placed: {item['object']}: {item['reason']}")


def _missing_defining(room: PlanRoom, done: RoomFurniture) -> list[str]:
    """The defining floor instances of ``room`` its furnishing could not place."""
    unplaced = {u["object"] for u in done.unplaced}
    return [
        instance
        for obj in room.objects
        if obj.defining and obj.placement == "floor"
        for instance in obj.instances()
        if instance in unplaced
    ]


def why_grow(room: PlanRoom, done: RoomFurniture) -> str:
    """Why ``room`` should grow after its furnishing ``done`` (empty when it need not): its
    defining furniture did not fit, or its furniture cut off free floor a robot cannot reach."""
    if _missing_defining(room, done):
        return f"its {', '.join(sorted({o.name for o in room.objects if o.defining}))} fits"
    share = done.layout.get("reachable_share")
    if share is not None and share < REGROW_SHARE:
        return f"its free floor stays reachable ({share:.0%} was)"
    return ""


def grow(plan: ScenePlan, why: dict[str, str]) -> tuple[ScenePlan, str]:
    """``plan`` with the rooms of ``why`` (room id -> the reason, in words) grown by ``GROWTH``
    in area, and what changed, in words."""
    rooms = [r for r in plan.rooms if r.id in why and r.area_m2 is not None]
    new_rooms = [
        r.model_copy(update={"area_m2": round(r.area_m2 * GROWTH, 1)})
        if r.id in why and r.area_m2 is not None
        else r
        for r in plan.rooms
    ]
    words = ", ".join(
        f"{r.id} from {r.area_m2:.1f} to {r.area_m2 * GROWTH:.1f} m² so that {why[r.id]}"
        for r in rooms
        if r.area_m2 is not None
    )
    return plan.model_copy(update={"rooms": new_rooms}), f"grew {words}"
