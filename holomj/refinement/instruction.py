"""An instruction, read with the offline planner's prompt parser into items to add, remove or move.

``"add a reading corner with an armchair and a floor lamp by the window"`` becomes two items to
add in the room that has a window: an armchair (by the window) and a floor lamp (by the window,
next to the armchair). How it reads:

- **Clauses.** The instruction is cut at ``then``, ``;``, ``.`` and at ``and`` / ``,`` before a
  verb ("remove the tv and add a plant"). A clause's first verb says what its objects are for:
  ``remove`` / ``delete`` / ``take away`` / ``get rid of`` remove them; ``move`` / ``shift`` /
  ``push`` / ``relocate`` (or ``put`` / ``place`` with "the X" that the scene has) move them;
  anything else adds them. "to the middle / corner / window / wall / door" reads as the place.
- **Objects and relations** are :func:`holomj.plan.prompt.parse_prompt`'s: kinds of the
  knowledge base with quantities and adjectives ("two red armchairs"), place relations ("by the
  window", "in the corner") and relations to other objects ("next to the sofa"; "the sofa" is a
  scene object when the scene has one). A noun the knowledge base does not know is added by its
  words (the edit plans it like its nearest kinds).
- **Groups.** Objects added in one clause share the place its last object is given ("an
  armchair and a floor lamp by the window": both by the window); when the clause names a zone
  ("a reading corner with ...", "a play area with ..."), the later ones also stand next to the
  first.
- **Rooms.** "in the bedroom" (a scene room's type, id or alias); else the room of a relation's
  target; else the group's room; else, among the rooms that have what a place relation needs
  (a window, a door), those whose type the kind belongs in, the largest.
- **Small objects** ("a vase on the coffee table") are dropped on their receptacle (``add_on``).

What cannot be used (an unknown room, a relation to nothing in the scene) is kept in ``notes``.
"""

from __future__ import annotations

import re

from holomj.evaluation.vocabulary import Vocabulary
from holomj.plan.knowledge import knowledge_base
from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.new_kinds import kind_name
from holomj.plan.prompt import ObjectRequest, ParsedPrompt, parse_prompt
from holomj.refinement.clauses import TO_PLACE, clause_verb, split_clauses
from holomj.refinement.instruction_items import Instruction, Item
from holomj.refinement.summary import ObjectInfo, PlannerSceneSummary, RoomInfo
from holomj.spec.relations import EDIT_KIND_OF, EDIT_PLACE_KINDS, kinds_about

MAX_QUANTITY = 6
PLURAL_QUANTITY = 2

ZONE_WORDS = ("corner", "nook", "area", "zone", "spot", "space", "station", "set up", "setup")
# Edit relation kinds (holomj.spec.edit) of the parser's relation kinds; the places among them.
EDIT_KINDS = EDIT_KIND_OF
PLACE_KINDS = frozenset(EDIT_PLACE_KINDS)


def read_instruction(
    text: str,
    scene: PlannerSceneSummary,
    kb: KnowledgeBase | None = None,
    vocab: Vocabulary | None = None,
) -> Instruction:
    """The items ``text`` asks of ``scene`` (see the module docstring); a kind's scene objects
    are those of its library category or of the categories the evaluator's vocabulary gives
    its name (``tv``: ``television``, ``wall_television``)."""
    kb = kb or knowledge_base()
    vocab = vocab or Vocabulary.load()
    result = Instruction(text=" ".join(text.split()), items=[])
    keys: dict[str, int] = {}
    for number, clause in enumerate(split_clauses(text)):
        action, body = clause_verb(clause)
        for pattern, place in TO_PLACE:
            body = re.sub(pattern, place, body)
        _Clause(number, action, body, scene, kb, vocab, result, keys).read()
    if not result.items:
        result.notes.append("the instruction names nothing to add, remove or move")
    return result


class _Clause:
    """Reads one clause into items of ``result``."""

    def __init__(
        self,
        number: int,
        action: str,
        text: str,
        scene: PlannerSceneSummary,
        kb: KnowledgeBase,
        vocab: Vocabulary,
        result: Instruction,
        keys: dict[str, int],
    ) -> None:
        self.number, self.action, self.text = number, action, text
        self.scene, self.kb, self.vocab, self.result, self.keys = scene, kb, vocab, result, keys
        self.parsed: ParsedPrompt = parse_prompt(text, kb)
        self.room = self._named_room()

    # -- reading

    def read(self) -> None:
        objects = [o for o in self.parsed.objects if not o.excluded]
        if self.action == "remove":
            for request in objects:
                self._remove(request)
            return
        targets = {r.target for r in self.parsed.relations if r.target is not None}
        made: dict[int, Item] = {}
        for index, request in enumerate(objects):
            existing = self._existing(request)
            reference = request.definite and bool(existing)
            if self.action == "move" or (self.action == "put" and reference):
                if index not in targets or not made:
                    made[index] = self._move(request, existing)
                continue
            if reference and index in targets:
                continue  # "next to the sofa": a scene object, not something to add
            made[index] = self._add(request)
        if not objects:
            for phrase in self.parsed.unknown:
                name = kind_name(phrase)
                if name and self.action in ("add", "put"):
                    made[len(made) + 100] = self._unknown(name, phrase)
        self._relations(objects, made)
        self._group([made[k] for k in sorted(made) if made[k].action == "add"])
        for item in made.values():
            self._finish(item)
            self.result.items.append(item)

    def _key(self, kind: str) -> str:
        slug = re.sub(r"[^a-z0-9]+", "_", kind.lower()).strip("_") or "object"
        self.keys[slug] = self.keys.get(slug, 0) + 1
        return slug if self.keys[slug] == 1 else f"{slug}_{self.keys[slug]}"

    def _kind(self, request: ObjectRequest) -> tuple[str, tuple[str, ...], str]:
        """(category hint, categories it may be, placement) of a requested kind."""
        kb = self.kb
        known = tuple(sorted(self.vocab.resolve(request.kind)))
        if request.kind in kb.objects:
            kind = kb.objects[request.kind]
            cats = tuple(dict.fromkeys((kind.category, *known)))
            return kind.category, cats, kind.placement
        if request.generic and request.kind in kb.generics:
            kinds = [kb.objects[k] for k in kb.generics[request.kind].kinds if k in kb.objects]
            cats = tuple(dict.fromkeys([*(k.category for k in kinds), *known]))
            placement = kinds[0].placement if kinds else "floor"
            return "", cats, placement
        slug = re.sub(r"[^a-z0-9]+", "_", request.kind.lower()).strip("_")
        return slug, tuple(dict.fromkeys((slug, *known))), "floor"

    def _quantity(self, request: ObjectRequest) -> int:
        if request.quantity is not None:
            return max(1, min(request.quantity, MAX_QUANTITY))
        if request.many:
            many = self.kb.objects[request.kind].many if request.kind in self.kb.objects else 4
            return min(many, MAX_QUANTITY)
        return PLURAL_QUANTITY if request.plural else 1

    def _existing(self, request: ObjectRequest) -> list[ObjectInfo]:
        _, categories, _ = self._kind(request)
        found = self.scene.of_category(set(categories), self.room)
        if not found and self.room is None:
            found = self.scene.of_category(set(categories))
        return found

    def _add(self, request: ObjectRequest) -> Item:
        category, categories, placement = self._kind(request)
        words = [*request.adjectives, request.kind]
        if request.size:
            words.insert(0, request.size)
        return Item(
            key=self._key(request.kind),
            action="add_on" if placement == "object" else "add",
            kind=request.kind,
            description=" ".join(words),
            category=category or None,
            categories=categories,
            placement=placement,
            quantity=self._quantity(request),
            room=self.room,
            phrase=request.phrase,
            clause=self.number,
        )

    def _unknown(self, name: str, phrase: str) -> Item:
        slug = re.sub(r"[^a-z0-9]+", "_", name).strip("_")
        self.result.notes.append(f"{name!r} is not in the knowledge base: added by its words")
        return Item(
            key=self._key(name),
            action="add",
            kind=name,
            description=phrase,
            category=None,
            categories=(slug,),
            placement="floor",
            quantity=1,
            room=self.room,
            phrase=phrase,
            clause=self.number,
        )

    def _remove(self, request: ObjectRequest) -> None:
        _, categories, placement = self._kind(request)
        found = self._existing(request)
        if not found:
            self.result.notes.append(f"nothing to remove: no {request.kind} in the scene")
            return
        if request.quantity is not None:
            chosen = found[: request.quantity]
        elif request.plural or request.many:
            chosen = found
        else:
            chosen = found[:1]
        rooms = list(dict.fromkeys(o.room for o in chosen))
        for room in rooms:
            self.result.items.append(
                Item(
                    key=self._key(request.kind),
                    action="remove",
                    kind=request.kind,
                    description=request.kind,
                    category=categories[0] if categories else None,
                    categories=categories,
                    placement=placement,
                    quantity=sum(1 for o in chosen if o.room == room),
                    room=room,
                    targets=[o.id for o in chosen if o.room == room],
                    phrase=request.phrase,
                    clause=self.number,
                )
            )

    def _move(self, request: ObjectRequest, existing: list[ObjectInfo]) -> Item:
        category, categories, placement = self._kind(request)
        if not existing:
            self.result.notes.append(f"no {request.kind} in the scene to move: it is added")
            return self._add(request)
        chosen = existing[: request.quantity or 1] if not request.plural else existing
        return Item(
            key=self._key(request.kind),
            action="move",
            kind=request.kind,
            description=request.kind,
            category=category or None,
            categories=categories,
            placement=placement,
            quantity=len(chosen),
            room=chosen[0].room,
            targets=[o.id for o in chosen],
            phrase=request.phrase,
            clause=self.number,
        )

    # -- relations, groups, rooms

    def _relations(self, objects: list[ObjectRequest], made: dict[int, Item]) -> None:
        for rel in self.parsed.relations:
            item = made.get(rel.subject)
            if item is None:
                continue
            if rel.kind == "on":
                target = self._target(objects, made, rel.target, item)
                if target is not None and not target.startswith("item:"):
                    item.on = target
                    item.room = item.room or (self.scene.object(target) or _NONE).room
                continue
            kind = EDIT_KINDS.get(rel.kind)
            if kind is None:
                self.result.notes.append(f"{rel.phrase!r} ({rel.kind}) is not an edit relation")
                continue
            if rel.target is None:
                item.relations.append((kind, None))
                continue
            target = self._target(objects, made, rel.target, item)
            if target is not None:
                item.relations.append((kind, target))

    def _target(
        self, objects: list[ObjectRequest], made: dict[int, Item], index: int | None, item: Item
    ) -> str | None:
        if index is None or index >= len(objects):
            return None
        if index in made and made[index].action in ("add", "add_on"):
            return f"item:{made[index].key}"
        if index in made and made[index].targets:
            return made[index].targets[0]
        request = objects[index]
        found = self._existing(request)
        if item.room is not None:
            found = [o for o in found if o.room == item.room] or found
        floor = [o for o in found if o.support is None]
        chosen = (floor or found)[:1]
        if not chosen:
            self.result.notes.append(
                f"{request.phrase!r}: no {request.kind} in the scene; relation not used"
            )
            return None
        return chosen[0].id

    def _group(self, items: list[Item]) -> None:
        floor = [i for i in items if i.placement == "floor"]
        if len(floor) < 2:
            return
        places = [r for i in floor for r in i.relations if r[1] is None and r[0] in PLACE_KINDS]
        shared = list(dict.fromkeys(places))
        zone = self._zone()
        first = floor[0]
        for k, item in enumerate(floor):
            if not any(r[1] is None for r in item.relations):
                item.relations = [*shared, *item.relations]
            has_object = any(r[1] is not None for r in item.relations)
            if zone and k > 0 and not has_object:
                item.relations.append(("adjacent_to", f"item:{first.key}"))

    def _zone(self) -> bool:
        head = self.text.split(" with ")[0] if " with " in self.text else ""
        return any(re.search(rf"\b{re.escape(w)}\b", head) for w in ZONE_WORDS)

    def _named_room(self) -> str | None:
        """The scene room the clause names ("in the bedroom"), if any."""
        best: tuple[int, str] | None = None
        for room in self.scene.rooms:
            for name in self._room_names(room):
                match = re.search(rf"\b(?:in|into|to)\s+(?:the\s+)?{re.escape(name)}\b", self.text)
                if match and (best is None or len(name) > best[0]):
                    best = (len(name), room.id)
        return best[1] if best else None

    def _room_names(self, room: RoomInfo) -> set[str]:
        names = {_words(room.type), _words(room.id)}
        template = self.kb.rooms.get(room.type)
        if template is not None:
            names |= {_words(a) for a in template.aliases}
        return {n for n in names if n}

    def _finish(self, item: Item) -> None:
        """Pick the item's room when the clause did not name one."""
        if item.room is None:
            item.room = self._room_for(item)
        if item.room is None:
            self.result.notes.append(f"no room for {item.kind!r}: the scene has no room")

    def _room_for(self, item: Item) -> str | None:
        for _, target in item.relations:
            if target is None:
                continue
            if target.startswith("item:"):
                other = self.result.item(target[5:])
                if other is not None and other.room:
                    return other.room
                continue
            obj = self.scene.object(target)
            if obj is not None and obj.room:
                return obj.room
        rooms = list(self.scene.rooms)
        kinds = {r[0] for r in item.relations}
        if kinds & kinds_about("window"):
            rooms = [r for r in rooms if r.windows] or rooms
        if kinds & kinds_about("door"):
            rooms = [r for r in rooms if r.doors] or rooms
        belongs = set()
        if item.kind in self.kb.objects:
            belongs = {
                self.kb.rooms[t].type
                for t in self.kb.objects[item.kind].rooms
                if t in self.kb.rooms
            }
        if not rooms:
            return None
        return max(rooms, key=lambda r: (r.type in belongs, r.area)).id


def _words(name: str) -> str:
    spaced = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", " ", name)
    return " ".join(re.findall(r"[a-z0-9]+", spaced.lower()))


class _None:
    room = None


_NONE = _None()
