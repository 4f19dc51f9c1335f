"""``light``: add a light fixture, or change a fixture or one of the scene's lights.

A scene without explicit lights is lit as the compiler lights it: a sun, and in each room a
point light under each light fixture (pendant, chandelier, ceiling light...; see
:data:`holomj.spec.decor.LIGHT_FIXTURE_CATEGORIES`), else one at the room's centre. So adding
a fixture to a room lights it from there; in a scene with explicit lights, the new fixture
gets its own point light (``energy``, ``color``). A fixture that is not a ceiling object (a
floor lamp) is added like any object (:func:`holomj.edit.objects.add`).
"""

from __future__ import annotations

from typing import Any

from holomj.edit.choice import choose_asset
from holomj.edit.describe import describe
from holomj.edit.footprints import room_at
from holomj.edit.lookup import kind_of, new_id, room_of
from holomj.edit.objects import add, replace
from holomj.edit.placing import ceiling_spot
from holomj.edit.state import Change, EditContext, Refused, find, rebuilt, with_objects
from holomj.spec.decor import LIGHT_BELOW_FIXTURE_M, LIGHT_FIXTURE_CATEGORIES
from holomj.spec.edit import AddOp, EditRelation, LightOp, ReplaceOp
from holomj.spec.scene import Light, SceneObject, SceneSpec

DEFAULT_FIXTURE = "a ceiling light"


def light(scene: SceneSpec, op: LightOp, ctx: EditContext, index: int) -> Change:
    """See :class:`holomj.spec.edit.LightOp`."""
    if op.id is not None:
        source = next((li for li in scene.lights if li.id == op.id), None)
        if source is not None:
            return _change_light(scene, op, source)
        return _change_fixture(scene, op, ctx, index)
    return _add_fixture(scene, op, ctx, index)


def _change_light(scene: SceneSpec, op: LightOp, source: Light) -> Change:
    if op.description is not None or op.above is not None:
        raise Refused(f"{op.id} is a light source: it takes position, energy, color and kind")
    update: dict[str, Any] = {}
    if op.position is not None:
        z = op.position[2] if len(op.position) == 3 else source.position[2]
        if room_at(scene, op.position[0], op.position[1]) is None:
            raise Refused(
                f"position ({op.position[0]:g}, {op.position[1]:g}) is outside every room"
            )
        if not 0.0 < z < scene.wall_height + 20.0:
            raise Refused(f"height {z:g} m is below the floor or far above the walls")
        update["position"] = (op.position[0], op.position[1], z)
    for name in ("energy", "color", "kind"):
        if getattr(op, name) is not None:
            update[name] = getattr(op, name)
    if not update:
        raise Refused("nothing to change: give position, energy, color or kind")
    lights = [li.model_copy(update=update) if li.id == source.id else li for li in scene.lights]
    new_scene = rebuilt(scene, lights=lights)
    return Change(new_scene, changed=[source.id], details={"light": source.id, **update})


def _change_fixture(scene: SceneSpec, op: LightOp, ctx: EditContext, index: int) -> Change:
    assert op.id is not None
    obj = find(scene, op.id)
    library = ctx.library
    if kind_of(obj, library) != "ceiling":
        raise Refused(f"{op.id} is not a light fixture on the ceiling nor a light of the scene")
    if op.energy is not None or op.color is not None or op.kind is not None:
        which = ", ".join(li.id for li in scene.lights) or "it has none: its fixtures light it"
        raise Refused(f"energy, color and kind are for the scene's own lights ({which})")
    change = Change(scene)
    if op.description is not None:
        change = replace(
            scene, ReplaceOp(op="replace", id=op.id, description=op.description), ctx, index
        )
    if op.position is not None or op.above is not None:
        current = find(change.scene, op.id)
        room_id = room_of(change.scene, current)
        if op.position is not None:
            room_id = room_at(change.scene, op.position[0], op.position[1]) or ""
            if not room_id:
                raise Refused(
                    f"position ({op.position[0]:g}, {op.position[1]:g}) is outside every room"
                )
        size = library.get(current.asset).meta.size if current.asset in library else (1, 1, 1)
        x, y, z = ceiling_spot(
            change.scene, room_id, size, ctx.library, at=op.position, above=op.above,
            exclude=frozenset({op.id}),
        )  # fmt: skip
        moved = current.model_copy(update={"position": (x, y, z), "room": room_id})
        objects = [moved if o.id == op.id else o for o in change.scene.objects]
        change.scene = with_objects(change.scene, objects)
        change.moved.append(op.id)
        change.why[op.id] = f"operation {index}: light moved"
        change.details["position"] = [x, y, z]
    if change.scene is scene:
        raise Refused("nothing to change: give description, position or above")
    return change


def _add_fixture(scene: SceneSpec, op: LightOp, ctx: EditContext, index: int) -> Change:
    room_id = op.room
    if room_id is None and op.above is not None:
        room_id = room_of(scene, find(scene, op.above))
    if room_id is None and op.position is not None:
        room_id = room_at(scene, op.position[0], op.position[1])
        if room_id is None:
            raise Refused(
                f"position ({op.position[0]:g}, {op.position[1]:g}) is outside every room"
            )
    if room_id is None and len(scene.rooms) == 1:
        room_id = scene.rooms[0].id
    if room_id is None:
        raise Refused("say which room (room, position or above)")
    if room_id not in {r.id for r in scene.rooms}:
        raise Refused(f"unknown room {room_id!r}")
    description = op.description or DEFAULT_FIXTURE
    asked = describe(description, scene.room(room_id).type, ctx.seed)
    if asked.placement != "ceiling":
        relations = [EditRelation(kind="near", target=op.above)] if op.above else []
        return add(
            scene,
            AddOp(
                op="add", description=description, room=room_id, position=op.position,
                relations=relations,
            ),
            ctx,
            index,
        )  # fmt: skip
    oid = new_id(scene, room_id, asked.name, None)
    asset_id, meta, pick = choose_asset(
        ctx, asked, attributes=[], category=asked.category, size=asked.size,
        placement="ceiling", key=("light", index), refuse_absurd=False,
    )  # fmt: skip
    x, y, z = ceiling_spot(scene, room_id, meta.size, ctx.library, at=op.position, above=op.above)
    obj = SceneObject(id=oid, asset=asset_id, position=(x, y, z), static=True, room=room_id)
    objects = [*scene.objects, obj]
    notes = []
    if meta.category not in LIGHT_FIXTURE_CATEGORIES:
        notes.append(f"a {meta.category} gives no light of its own")
    lights = list(scene.lights)
    if scene.lights:
        lights = [
            *scene.lights,
            Light(
                id=f"{oid}.light",
                position=(x, y, max(z - LIGHT_BELOW_FIXTURE_M, 0.5)),
                energy=op.energy if op.energy is not None else 1.0,
                color=op.color or (1.0, 1.0, 1.0),
                kind=op.kind or "point",
            ),
        ]
    elif op.energy is not None or op.color is not None or op.kind is not None:
        notes.append(
            "energy, color and kind are for explicit lights; this scene is lit by its fixtures"
        )
    new_scene = rebuilt(scene, objects=objects, lights=lights)
    return Change(
        new_scene,
        added=[oid],
        notes=notes,
        details={"room": room_id, "position": [x, y, z], **pick},
    )
