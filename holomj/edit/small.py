"""Small objects: ``add_on`` (retrieve, then spawn-and-drop onto a receptacle), and dropping the
small objects of a replaced receptacle again (or a small object ``move``d onto another one).

Drops use :func:`holomj.physics.spawn.populate`: candidate poses on the receptacle's support
surfaces, rejected when they collide at spawn, dropped and settled with the simulator, accepted
only when they rest on that receptacle. Nothing else in the scene moves.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

from holomj.edit.describe import describe
from holomj.edit.state import Change, EditContext, Refused, find, resting_on, with_objects
from holomj.errors import HolomjError
from holomj.physics.spawn import populate
from holomj.physics.surfaces_world import world_surfaces
from holomj.plan.new_kinds import kind_name
from holomj.spec.edit import AddOnOp, MoveOp
from holomj.spec.scene import SceneSpec

MAX_ATTEMPTS = 20


def drop(
    scene: SceneSpec,
    ctx: EditContext,
    receptacle_id: str,
    assets: Sequence[str],
    *,
    rng_key: tuple[object, ...],
    ids: Sequence[str | None] | None = None,
) -> tuple[SceneSpec, list[str], list[dict[str, Any]]]:
    """Drop one object of each asset onto ``receptacle_id``: the scene with those that came to
    rest on it, their ids (``ids`` where given, else made from the category) and a record of
    every attempt."""
    receptacle = find(scene, receptacle_id)
    library = ctx.library
    if not world_surfaces(receptacle, library.get(receptacle.asset).meta):
        raise Refused(
            f"{receptacle_id!r} has no support surfaces (choose a table, desk, shelf or other "
            "receptacle)"
        )
    if not assets:
        return scene, [], []
    try:
        result = populate(
            scene,
            library,
            receptacle_id,
            [(a, 1) for a in assets],
            ctx.rng(*rng_key),
            max_attempts=MAX_ATTEMPTS,
            attach=ctx.attach,
        )
    except HolomjError as err:
        raise Refused(err.one_line()) from None
    wanted = list(ids) if ids is not None else [None] * len(assets)
    rename = {
        p.object_id: want
        for p, want in zip(result.placements, wanted)
        if p.accepted and want is not None
    }
    objects = [
        o.model_copy(update={"id": rename[o.id]}) if o.id in rename else o
        for o in result.scene.objects
    ]
    new_scene = with_objects(result.scene, objects) if rename else result.scene
    placed = [rename.get(p.object_id, p.object_id) for p in result.placements if p.accepted]
    record = [
        {
            "id": rename.get(p.object_id, p.object_id),
            "asset": p.asset,
            "accepted": p.accepted,
            "reason": p.reason,
            "attempts": p.attempts,
        }
        for p in result.placements
    ]
    return new_scene, placed, record


def category_words(category: str) -> str:
    """``coffee_table`` -> ``coffee table``."""
    return " ".join(re.findall(r"[a-z0-9]+", category.lower())) or "table"


def add_on(scene: SceneSpec, op: AddOnOp, ctx: EditContext, index: int) -> Change:
    """``add_on``: retrieve ``count`` small objects for the description and drop them."""
    receptacle = find(scene, op.on)
    library = ctx.library
    meta = library.get(receptacle.asset).meta
    room_type = scene.room(receptacle.room).type if receptacle.room else "room"
    asked = describe(
        f"{op.description} on the {category_words(meta.category)}", room_type, ctx.seed
    )
    if asked.placement != "object" and op.category is None:
        raise Refused(
            f"{op.description!r} is not a small object ({asked.name} is a {asked.placement} "
            "object): use 'add'"
        )
    words = " ".join([kind_name(op.description) or asked.description, *op.attributes])
    category = op.category or asked.category
    try:
        picks = ctx.retriever.choose(
            words,
            quantity=op.count,
            variance="varied",
            rng=ctx.rng("add_on", index, "retrieve"),
            placement="object",
            category=category,
        )
    except HolomjError as err:
        raise Refused(f"no asset for {op.description!r}: {err.one_line()}") from None
    assets = [p.asset_id for p in picks]
    new_scene, placed, record = drop(scene, ctx, op.on, assets, rng_key=("add_on", index, "drop"))
    if not placed:
        why = "; ".join(sorted({r["reason"] for r in record})) or "nothing placed"
        raise Refused(f"no {asked.name} came to rest on {op.on}: {why}")
    notes = []
    if len(placed) < op.count:
        notes.append(f"{len(placed)} of {op.count} placed on {op.on}")
    return Change(
        new_scene,
        added=placed,
        notes=notes,
        details={
            "on": op.on,
            "category": category,
            "assets": assets,
            "how": sorted({getattr(p, "how", "ranked") for p in picks}),
            "drops": record,
        },
    )


def move_onto(scene: SceneSpec, op: MoveOp, ctx: EditContext, index: int) -> Change:
    """``move`` with ``on``: a small object dropped onto another receptacle (keeping its id)."""
    assert op.on is not None  # the caller's dispatch
    obj = find(scene, op.id)
    find(scene, op.on)
    if obj.support is None:
        raise Refused(f"{op.id} is not a small object on a receptacle ('on' moves those)")
    if op.on == op.id or op.on in {o.id for o in resting_on(scene, op.id)}:
        raise Refused(f"{op.id} cannot rest on itself")
    riders = resting_on(scene, op.id)
    if riders:
        raise Refused(f"{', '.join(o.id for o in riders)} rest on {op.id}: move them first")
    without = with_objects(scene, [o for o in scene.objects if o.id != op.id])
    new_scene, placed, record = drop(
        without, ctx, op.on, [obj.asset], rng_key=("move", index), ids=[op.id]
    )
    if not placed:
        raise Refused(f"{op.id} found no place on {op.on}: {record[0]['reason']}")
    return Change(new_scene, moved=[op.id], details={"on": op.on, "drops": record})
