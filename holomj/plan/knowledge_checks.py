"""Consistency checks over the knowledge base: the files must agree with each other.

Sizes within the sane ranges of their placement, every name a file uses known to the file that
defines it, phrases that name one thing only, room templates whose layout lines parse and whose
defining kinds are always planned, scene types whose rooms exist.
"""

from __future__ import annotations

from collections.abc import Iterable

from holomj.errors import SpecError, closest_names
from holomj.layout.constraints import parse_constraint_text
from holomj.plan.knowledge_schema import (
    KnowledgeBase,
    RoomTemplate,
    SceneType,
    TemplateObject,
)

# Sane (width, depth, height) ranges in metres, per placement: sizes outside are data errors.
SIZE_RANGES: dict[str, tuple[tuple[float, float], tuple[float, float], tuple[float, float]]] = {
    "floor": ((0.1, 6.0), (0.05, 6.0), (0.01, 4.0)),
    "wall": ((0.05, 5.0), (0.01, 1.0), (0.05, 3.0)),
    "ceiling": ((0.05, 4.0), (0.05, 4.0), (0.02, 2.0)),
    "object": ((0.005, 1.0), (0.005, 1.0), (0.005, 1.0)),
}
MAX_FOOTPRINT_M2 = 16.0  # one floor object's width x depth
DEFINING_PRIORITY = 8  # the lowest priority a defining kind may have in its template


def check_knowledge(kb: KnowledgeBase) -> None:
    """Raise a SpecError for the first disagreement between the knowledge files."""
    _check_sizes(kb)
    _check_objects(kb)
    _check_phrases(kb)
    for name, template in kb.rooms.items():
        _check_template(kb, name, template)
    for name, scene in kb.scene_types.items():
        _check_scene(kb, name, scene)


def _unknown(name: str, known: Iterable[str], what: str, where: str) -> SpecError:
    close = closest_names(name, known)
    return SpecError(
        f"unknown {what} {name!r}", where=where, fix=f"did you mean {close}" if close else None
    )


def _check_sizes(kb: KnowledgeBase) -> None:
    """Sizes within the sane ranges of their placement; small <= default <= large."""
    for name, kind in kb.objects.items():
        ranges = SIZE_RANGES[kind.placement]
        sizes = {"size": kind.size, "small": kind.small, "large": kind.large}
        for key, size in sizes.items():
            if size is None:
                continue
            where = f"objects.json: objects.{name}.{key}"
            for axis, value, (low, high) in zip(("width", "depth", "height"), size, ranges):
                if not low <= value <= high:
                    raise SpecError(
                        f"{axis} {value:g} m is outside the sane range {low:g}-{high:g} m "
                        f"for {kind.placement} objects",
                        where=where,
                    )
            if kind.placement == "floor" and size[0] * size[1] > MAX_FOOTPRINT_M2:
                raise SpecError(
                    f"footprint {size[0] * size[1]:.1f} m2 is larger than {MAX_FOOTPRINT_M2:g} m2",
                    where=where,
                )
        if kind.size is None:
            continue
        default = _measures(kind.placement, kind.size)
        for key, size, sign in (("small", kind.small, -1), ("large", kind.large, 1)):
            if size is None:
                continue
            measures = _measures(kind.placement, size)
            if all(sign * (m - d) < 0 for m, d in zip(measures, default)):
                relation = "smaller" if sign > 0 else "larger"
                raise SpecError(
                    f"the {key} size {list(size)} is {relation} than the default size "
                    f"{list(kind.size)} (in area and in volume)",
                    where=f"objects.json: objects.{name}.{key}",
                )


def _measures(placement: str, size: tuple[float, float, float]) -> tuple[float, float]:
    """(visible area, volume) of a size: the face of wall objects, else the footprint."""
    width, depth, height = size
    area = width * height if placement == "wall" else width * depth
    return area, width * depth * height


def _check_objects(kb: KnowledgeBase) -> None:
    floor = {n for n, k in kb.objects.items() if k.placement == "floor"}
    receptacles = _receptacle_categories(kb)
    for name, kind in kb.objects.items():
        where = f"objects.json: objects.{name}"
        for room in kind.rooms:
            if room not in kb.rooms:
                raise _unknown(room, kb.rooms, "room template", f"{where}.rooms")
        if len(set(kind.rooms)) != len(kind.rooms):
            repeated = next(r for r in kind.rooms if kind.rooms.count(r) > 1)
            raise SpecError(f"room template {repeated!r} listed twice", where=f"{where}.rooms")
        has_table = kind.placement == "floor" and kind.category in receptacles
        if kind.receptacle and not has_table:
            raise SpecError(
                f"marked receptacle, but the receptacle table lists no small objects for "
                f"category {kind.category!r}",
                where=f"{where}.receptacle",
                fix="add the category to receptacles.json or set receptacle to false",
            )
        if has_table and not kind.receptacle:
            raise SpecError(
                f"the receptacle table lists small objects for category {kind.category!r}: "
                "set receptacle to true",
                where=f"{where}.receptacle",
            )
        if kind.placement == "object" and not any(
            kind.category in kb.allowed_small(rec) for rec in _receptacle_categories(kb)
        ):
            raise SpecError(
                f"small object category {kind.category!r} fits no receptacle", where=where
            )
        for i, line in enumerate(kind.constraints):
            subject = line.split("|", 1)[0].strip()
            if subject != name:
                raise SpecError(
                    f"a default constraint line must start with {name!r}, not {subject!r}",
                    where=f"{where}.constraints[{i}]",
                )
            for target in _targets(line):
                if target not in floor:
                    raise _unknown(target, floor, "floor object", f"{where}.constraints[{i}]")
            _check_lines([line], [name, *_targets(line)], f"{where}.constraints[{i}]")
    for name, generic in kb.generics.items():
        for member in generic.kinds:
            if member not in kb.objects:
                raise _unknown(member, kb.objects, "object kind", f"objects.json: generics.{name}")
    for name in kb.refused:
        if name in kb.objects:
            raise SpecError(
                "a refused thing cannot also be an object kind", where=f"refused.{name}"
            )


def _receptacle_categories(kb: KnowledgeBase) -> set[str]:
    return {key.split(":")[-1] for key in kb.receptacles}


def _check_phrases(kb: KnowledgeBase) -> None:
    """A phrase may name one object kind, generic, refused thing, room template or style."""
    owners: dict[str, str] = {}

    def claim(phrases: Iterable[str], owner: str) -> None:
        for phrase in phrases:
            if phrase in owners and owners[phrase] != owner:
                raise SpecError(
                    f"the phrase {phrase!r} names both {owners[phrase]} and {owner}",
                    where=f"{owner}.aliases",
                    fix="keep each alias in one place",
                )
            owners[phrase] = owner

    for name, kind in kb.objects.items():
        claim([name, *kind.aliases], f"objects.json: objects.{name}")
    for name, generic in kb.generics.items():
        claim(generic.aliases, f"objects.json: generics.{name}")
    for name, refused in kb.refused.items():
        claim(refused.aliases, f"objects.json: refused.{name}")
    for name, template in kb.rooms.items():
        claim(template.aliases, f"rooms.json: rooms.{name}")
    for name, style in kb.styles.items():
        claim(style.aliases, f"styles.json: styles.{name}")
    keywords: dict[str, str] = {}
    for name, scene in kb.scene_types.items():
        for keyword in scene.keywords:
            if keyword in keywords:
                raise SpecError(
                    f"keyword {keyword!r} names scene types {keywords[keyword]!r} and {name!r}",
                    where=f"scene_types.json: scene_types.{name}.keywords",
                )
            keywords[keyword] = name


def _check_template(kb: KnowledgeBase, name: str, template: RoomTemplate) -> None:
    where = f"rooms.json: rooms.{name}"
    if template.counts_as is not None and template.counts_as not in kb.rooms:
        raise _unknown(template.counts_as, kb.rooms, "room template", f"{where}.counts_as")
    for neighbour in template.neighbours:
        if neighbour not in kb.rooms:
            raise _unknown(neighbour, kb.rooms, "room template", f"{where}.neighbours")
    for variant, objects, lines in template.object_sets():
        here = where if variant == "base" else f"{where} (variant {variant!r})"
        names = [o.object for o in objects]
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise SpecError(f"object {dupes[0]!r} listed twice", where=here)
        for i, entry in enumerate(objects):
            _check_entry(kb, template.type, entry, names, f"{here}.objects[{i}]")
            _check_belongs(kb, name, entry)
        floor = [n for n in names if kb.objects[n].placement == "floor"]
        _check_lines(lines, floor, f"{here}.constraints")
    _check_defining(kb, name, template)


def _check_belongs(kb: KnowledgeBase, template: str, entry: TemplateObject) -> None:
    """A kind a template lists (on the floor, a wall or a receptacle) names it in its rooms."""
    listed = [entry.object]
    if isinstance(entry.on_top, list):
        listed += [item.object for item in entry.on_top]
    for name in listed:
        if template not in kb.objects[name].rooms:
            raise SpecError(
                f"rooms.json: rooms.{template} lists {name!r}, but {template!r} is not in its "
                "rooms",
                where=f"objects.json: objects.{name}.rooms",
            )


def _check_defining(kb: KnowledgeBase, name: str, template: RoomTemplate) -> None:
    """Defining kinds: known floor or wall kinds the template always has when it lists them."""
    where = f"rooms.json: rooms.{name}.defining"
    if len(set(template.defining)) != len(template.defining):
        repeated = next(k for k in template.defining if template.defining.count(k) > 1)
        raise SpecError(f"defining kind {repeated!r} listed twice", where=where)
    kinds = template.kinds()
    for kind_name in template.defining:
        kind = kb.objects.get(kind_name)
        if kind is None:
            raise _unknown(kind_name, kb.objects, "object kind", where)
        if kind.placement not in ("floor", "wall"):
            raise SpecError(
                f"defining kind {kind_name!r} is a {kind.placement} object: only floor and wall "
                "objects define a room",
                where=where,
            )
        if kind_name not in kinds:
            raise _unknown(kind_name, kinds, "object of this template", where)
    for variant, objects, _ in template.object_sets():
        here = where if variant == "base" else f"{where} (variant {variant!r})"
        by_name = {o.object: o for o in objects}
        for kind_name in template.defining_in(by_name):
            entry = by_name[kind_name]
            if entry.priority < DEFINING_PRIORITY or entry.probability < 1.0:
                raise SpecError(
                    f"defining kind {kind_name!r} has priority {entry.priority} and probability "
                    f"{entry.probability:g}: it needs priority >= {DEFINING_PRIORITY} and "
                    "probability 1",
                    where=here,
                )
            for anchor, what in ((entry.per, "counts per"), (entry.above, "hangs above")):
                if anchor is not None and anchor not in template.defining:
                    raise SpecError(
                        f"defining kind {kind_name!r} {what} {anchor!r}, which is not defining",
                        where=here,
                    )


def _check_entry(
    kb: KnowledgeBase, room_type: str, entry: TemplateObject, names: list[str], where: str
) -> None:
    kind = kb.objects.get(entry.object)
    if kind is None:
        raise _unknown(entry.object, kb.objects, "object kind", where)
    if kind.placement == "object":
        raise SpecError(
            f"{entry.object!r} is a small object: list it in a receptacle's on_top", where=where
        )
    if entry.above is not None:
        if kind.placement != "wall":
            raise SpecError("only wall objects hang above others", where=where)
        if entry.above not in names or kb.objects[entry.above].placement != "floor":
            raise _unknown(entry.above, names, "floor object of this room", f"{where}.above")
    if entry.per is not None and entry.per not in names:
        raise _unknown(entry.per, names, "object of this room", f"{where}.per")
    if entry.on_top is not None:
        if not kind.receptacle:
            raise SpecError(
                f"{entry.object!r} is not a receptacle (receptacle: false)", where=f"{where}.on_top"
            )
        choices = kb.small_choices(room_type, kind.category)
        if not choices:
            raise SpecError(f"{kind.category!r} is not a receptacle", where=f"{where}.on_top")
        allowed = {name for name, _ in choices}
        small_categories = {k.category for k in kb.objects.values() if k.placement == "object"}
        unknown = sorted(allowed - small_categories)
        if unknown:
            raise SpecError(
                f"no small object kind of category {unknown[0]!r} (receptacle table entry for "
                f"{kind.category!r} in {room_type!r})",
                where=f"{where}.on_top",
            )
        if entry.on_top != "auto":
            for j, item in enumerate(entry.on_top):
                small = kb.objects.get(item.object)
                if small is None or small.placement != "object":
                    smalls = [n for n, k in kb.objects.items() if k.placement == "object"]
                    raise _unknown(item.object, smalls, "small object", f"{where}.on_top[{j}]")
                if small.category not in allowed:
                    raise SpecError(
                        f"{small.category!r} does not go on {kind.category!r} "
                        f"(allowed: {', '.join(sorted(allowed))})",
                        where=f"{where}.on_top[{j}]",
                    )


def _check_lines(lines: list[str], names: list[str], where: str) -> None:
    """Every line parses without warnings over ``names``."""
    for i, line in enumerate(lines):
        parsed = parse_constraint_text(line, names)
        if parsed.warnings or not parsed.constraints:
            problem = parsed.warnings[0] if parsed.warnings else "no constraint in it"
            raise SpecError(f"constraint {line!r}: {problem}", where=f"{where}[{i}]")


def _targets(line: str) -> list[str]:
    """Target names of a constraint line (the text after the comma of each segment)."""
    out = []
    for segment in line.split("|")[1:]:
        if "," in segment:
            out.append(" ".join(segment.split(",", 1)[1].split()))
    return out


def _check_scene(kb: KnowledgeBase, name: str, scene: SceneType) -> None:
    where = f"scene_types.json: scene_types.{name}"
    ids = [room.id for room in scene.rooms]
    dupes = sorted({i for i in ids if ids.count(i) > 1})
    if dupes:
        raise SpecError(f"room id {dupes[0]!r} repeats", where=f"{where}.rooms")
    if scene.entrance not in ids:
        raise _unknown(scene.entrance, ids, "room id", f"{where}.entrance")
    if scene.refines is not None and scene.refines not in kb.scene_types:
        raise _unknown(scene.refines, kb.scene_types, "scene type", f"{where}.refines")
    for i, room in enumerate(scene.rooms):
        if room.template not in kb.rooms:
            raise _unknown(room.template, kb.rooms, "room template", f"{where}.rooms[{i}].template")
        for other in room.adjacent_to:
            if other not in ids or other == room.id:
                raise _unknown(other, ids, "room id", f"{where}.rooms[{i}].adjacent_to")
