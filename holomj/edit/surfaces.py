"""``material``: a room's floor, walls or ceiling.

The material is a name (one the scene defines, a built-in or a user material allowed on that
surface) or a description, matched like ``generate`` matches the plan's material words
(:mod:`holomj.retrieval.materials`: sentence-embedding similarity to each material's name and
description); a description closer than :data:`MATCH_MIN` to no material is refused as unknown,
naming the nearest.
"""

from __future__ import annotations

import re

from holomj.edit.state import Change, EditContext, Refused, rebuilt
from holomj.errors import closest_names
from holomj.spec.edit import MaterialOp
from holomj.spec.materials import BUILTIN_MATERIALS, Material
from holomj.spec.scene import SceneSpec

MATCH_MIN = 0.3  # below this cosine a description names no material ("zxqv", "banana")
FIELDS = {"floor": "floor_material", "wall": "wall_material", "ceiling": "ceiling_material"}


def choose(
    ctx: EditContext, scene: SceneSpec, text: str, surface: str
) -> tuple[str, Material, str]:
    """The material ``text`` means on ``surface``: name, look and how it was found."""
    library = ctx.material_library
    allowed = library.for_surface(surface)
    wanted = "_".join(re.findall(r"[a-z0-9]+", text.lower()))
    for name, material in scene.materials.items():
        if name.lower() == wanted:
            return name, material, "the scene's own"
    for entry in allowed:
        if entry.name.lower() == wanted:
            return entry.name, entry.material, "by name"
    if any(e.name.lower() == wanted for e in library.entries):
        raise Refused(f"material {text!r} is not for a {surface}")
    rows = {e.name: k for k, e in enumerate(library.entries)}
    matrix = library.vectors(ctx.encoder)[[rows[e.name] for e in allowed]]
    scores = matrix @ library.query(ctx.encoder, text)
    best = min(range(len(allowed)), key=lambda k: (-float(scores[k]), allowed[k].name))
    score = float(scores[best])
    if score < MATCH_MIN:
        near = closest_names(wanted, [e.name for e in allowed])
        hint = f"; names close to it: {near}" if near else ""
        raise Refused(
            f"unknown material {text!r} for a {surface} (nearest {allowed[best].name!r}, "
            f"similarity {score:.2f} < {MATCH_MIN}){hint}"
        )
    return allowed[best].name, allowed[best].material, f"matched (similarity {score:.2f})"


def material(scene: SceneSpec, op: MaterialOp, ctx: EditContext, index: int) -> Change:
    """``material``: see :class:`holomj.spec.edit.MaterialOp`."""
    surface = "wall" if op.surface in ("wall", "walls") else op.surface
    ids = [r.id for r in scene.rooms]
    if op.room is not None and op.room not in ids:
        near = closest_names(op.room, ids)
        raise Refused(f"unknown room {op.room!r}" + (f"; did you mean {near}?" if near else ""))
    name, look, how = choose(ctx, scene, op.material, surface)
    field = FIELDS[surface]
    rooms = [
        r.model_copy(update={field: name}) if op.room in (None, r.id) else r for r in scene.rooms
    ]
    materials = dict(scene.materials)
    if name not in BUILTIN_MATERIALS:
        materials[name] = look
    new_scene = rebuilt(scene, rooms=rooms, materials=materials)
    touched = [r.id for r in scene.rooms if op.room in (None, r.id)]
    notes = []
    if surface == "ceiling" and not scene.ceilings:
        notes.append("the scene has no ceilings: the material is recorded but not seen")
    return Change(
        new_scene,
        changed=[f"{room}.{op.surface}" for room in touched],
        notes=notes,
        details={"material": name, "how": how, "surface": surface, "rooms": touched},
    )
