"""Layout wishes of an edit: the relations an operation asks, those its description's words
gave, and a kind's default layout lines, as :class:`holomj.edit.floor.Wish` over the room's
objects."""

from __future__ import annotations

from collections.abc import Sequence

from holomj.edit.describe import Described
from holomj.edit.floor import Wish
from holomj.edit.footprints import in_room
from holomj.edit.lookup import category_of, room_of
from holomj.edit.state import (
    Refused,
    find,
)
from holomj.layout.constraints import PHRASES, RELATION_WEIGHT, normalize_phrase
from holomj.library.store import AssetLibrary
from holomj.plan.knowledge import knowledge_base
from holomj.spec.edit import EditRelation
from holomj.spec.relations import EDIT_CONSTRAINTS
from holomj.spec.scene import SceneSpec

# Edit relation kinds -> layout constraint kinds (several: all of them).
CONSTRAINTS = EDIT_CONSTRAINTS


def wishes_of(
    scene: SceneSpec, room_id: str, relations: Sequence[EditRelation], floor_ids: set[str]
) -> list[Wish]:
    """Layout wishes of explicit relations (targets: object ids of the room)."""
    out = []
    for rel in relations:
        if rel.kind == "above":
            continue
        if rel.target is not None:
            target = find(scene, rel.target)
            if room_of(scene, target) != room_id:
                raise Refused(f"{rel.target} is not in room {room_id!r}")
            if rel.target not in floor_ids:
                raise Refused(f"{rel.target} is not an object the layout can relate to")
        for kind in CONSTRAINTS[rel.kind]:
            source = f"{rel.kind} {rel.target or ''}".strip()
            out.append(Wish(kind, rel.target, RELATION_WEIGHT, source))
    return out


def _match(
    scene: SceneSpec, room_id: str, name: str, library: AssetLibrary, floor_ids: set[str]
) -> str | None:
    """The object of the room a plan name means: one of the kind's category, else one whose id
    names it."""
    kb = knowledge_base()
    category = kb.objects[name].category if name in kb.objects else name.replace(" ", "_")
    stem = name.replace(" ", "_")
    candidates = [o for o in scene.objects if o.id in floor_ids and in_room(scene, o, room_id)]
    for obj in candidates:
        if category_of(obj, library) == category:
            return obj.id
    for obj in candidates:
        if stem in obj.id.rsplit(".", 1)[-1]:
            return obj.id
    return None


def described_wishes(
    scene: SceneSpec,
    room_id: str,
    asked: Described,
    library: AssetLibrary,
    floor_ids: set[str],
    notes: list[str],
) -> tuple[list[Wish], str | None]:
    """Wishes from the relations the description's words gave (targets matched to the room's
    objects), and the target of an ``above``; relations that name nothing here are noted."""
    out: list[Wish] = []
    above = None
    for kind, target in asked.relations:
        if kind in ("on", "ceiling"):
            continue
        target_id = None
        if target is not None:
            target_id = _match(scene, room_id, target, library, floor_ids)
            if target_id is None:
                notes.append(f"'{kind} {target}': no {target} in {room_id}; not used")
                continue
        if kind == "above":
            above = target_id
            continue
        if kind not in CONSTRAINTS:
            notes.append(f"'{kind}' cannot be used for one object; not used")
            continue
        source = f"{kind} {target or ''}".strip()
        out.extend(Wish(k, target_id, RELATION_WEIGHT, source) for k in CONSTRAINTS[kind])
    return out, above


def default_wishes(
    scene: SceneSpec, room_id: str, name: str, library: AssetLibrary, floor_ids: set[str]
) -> list[Wish]:
    """The kind's default layout lines (``armchair | near, coffee table | face to, coffee
    table``) with weight 1, over the room's objects; floor objects without any stand against a
    wall."""
    kb = knowledge_base()
    lines = kb.objects[name].constraints if name in kb.objects else [f"{name} | edge"]
    out: list[Wish] = []
    for line in lines:
        for part in line.split("|")[1:]:
            phrase, _, target = (s.strip() for s in part.partition(","))
            kinds = PHRASES.get(normalize_phrase(phrase), ())
            target_id = None
            if target:
                target_id = _match(scene, room_id, target.rsplit("-", 1)[0], library, floor_ids)
                if target_id is None:
                    continue
            out.extend(Wish(k, target_id, 1.0, f"default: {part.strip()}") for k in kinds)
    return out or [Wish("edge", None, 1.0, "default: against a wall")]
