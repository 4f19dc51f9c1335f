"""Fidelity to a request: object counts, attributes, relations, absent things and defining
furniture of a scene, against an annotation (the format of ``scripts/eval/prompts_dev.jsonl``,
or one made from a plan by :mod:`holomj.evaluation.plan_spec`).

- **Names.** An annotation name is normalised (lower case, ``_``/``-`` as spaces, articles and
  ``'s`` dropped), looked up in the vocabulary (names and synonyms, then singular forms) and
  becomes a set of library categories; an unknown name maps to itself (``arcade cabinet`` ->
  ``arcade_cabinet``). A scene object's labels are its ``category`` (objects.json, else its
  asset.json) and, when that is missing or generic (``box``: ``builtin:box`` proxies), the noun of
  its id (``kitchen.arcade_cabinet_0`` -> ``arcade_cabinet``) and the categories the vocabulary
  gives that noun. An annotation object made from a plan may also carry ``categories`` (the
  plan's category hint), ``room_id`` (one scene room) and ``id_stem`` (the ids the plan's own
  scene gave its instances: ``living_room.sofa`` matches ``living_room.sofa_0``, ...); such an
  annotation may list ``references``: objects not counted, whose entries relations look up.
- **Counts.** Objects whose labels meet the name's categories (in rooms of the spec's room type
  when given), compared with ``eq``/``ge``. Room totals and room types count scene rooms.
- **Attributes** (:mod:`holomj.evaluation.attributes`): at least n instances (n = the spec's
  count) must have it.
- **Relations** (:mod:`holomj.evaluation.relations`): subject and object must share a room;
  ``quantifier``: ``any`` (default), ``all`` or ``most`` (75 %) of the subject's instances.
- **Absent.** No object of the name; a room-type name means no such room; ``window``/``door``
  mean no such opening.
- **Defining furniture.** Every scene room whose type has a rule in the vocabulary (bedroom: bed;
  bathroom: toilet, washbasin; kitchen: fridge, stove, sink; living room: sofa; office: desk,
  chair; dining room: table, 2 chairs) holds it, and every room type the annotation lists exists.
- **Validation.** ``report.json`` says ``ok``.
- **Doors** and **reachability**: :mod:`holomj.evaluation.openings`,
  :mod:`holomj.evaluation.reachability`.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from holomj.evaluation import quantified as quantified_
from holomj.evaluation.attributes import object_colours, object_has_shape, object_materials
from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.objects import EvaluatedObject, EvaluatedRoom
from holomj.evaluation.openings import door_clearance
from holomj.evaluation.reachability import reachability
from holomj.evaluation.relations import RELATIONS, Verdict
from holomj.evaluation.text import normalise
from holomj.evaluation.vocabulary import Vocabulary


class Scorer:
    """Scores one scene folder against one annotation."""

    def __init__(
        self,
        folder: Path,
        spec: dict[str, Any],
        vocab: Vocabulary | None = None,
        scene: MeasuredFolder | None = None,
    ):
        self.scene = scene if scene is not None else MeasuredFolder(folder)
        self.spec = spec
        self.vocab = vocab or Vocabulary.load()
        label_objects(self.scene, self.vocab)

    # -- selection

    def rooms_of_type(self, room_name: str | None) -> list[EvaluatedRoom] | None:
        """The scene's rooms of an annotation's room type (None: no restriction)."""
        if not room_name:
            return None
        canon = self.vocab.room_canonical(room_name) or normalise(room_name)
        return [r for r in self.scene.rooms if self.vocab.room_is(r, canon)]

    def entry(self, name: str, room_id: str | None = None) -> dict[str, Any] | None:
        """The annotation's object entry of ``name`` (in the room ``room_id`` when given)."""
        key = normalise(name)
        entries = [*self.spec.get("objects", []), *self.spec.get("references", [])]
        found = [o for o in entries if normalise(o["name"]) == key]
        for o in found:
            if room_id is None or o.get("room_id") == room_id:
                return o
        return found[0] if found else None

    def instances(
        self, name: str, room_name: str | None = None, entry: dict[str, Any] | None = None
    ) -> list[EvaluatedObject]:
        """The scene's objects that count as ``name`` (in rooms of ``room_name`` when given; in the
        room and with the ids or categories that ``entry`` names, when it names them)."""
        entry = entry or {}
        room_id = entry.get("room_id")
        if room_id is not None and room_id in self.scene.room_by_id:
            ids: set[str] | None = {room_id}
        else:
            rooms = self.rooms_of_type(room_name)
            ids = None if rooms is None else {r.id for r in rooms}
        if entry.get("id_stem"):
            pattern = re.compile(re.escape(entry["id_stem"]) + r"_\d+$")
            return [o for o in self.scene.objects if pattern.match(o.id)]
        cats = self.vocab.resolve(name) | {c.lower() for c in entry.get("categories") or []}
        return [o for o in self.scene.objects if o.labels & cats and (ids is None or o.room in ids)]

    def _object_room(self, name: str) -> str | None:
        for o in self.spec.get("objects", []):
            if normalise(o["name"]) == normalise(name):
                return o.get("room")
        return None

    # -- specs

    @staticmethod
    def _count_ok(count: dict[str, int], n: int) -> bool:
        if "eq" in count:
            return n == int(count["eq"])
        return n >= int(count.get("ge", 1))

    @staticmethod
    def _count_text(count: dict[str, int]) -> str:
        return f"eq {count['eq']}" if "eq" in count else f"ge {count.get('ge', 1)}"

    def counts(self) -> list[dict[str, Any]]:
        """Object counts, the room total and room-type counts."""
        out = []
        rooms = self.spec.get("rooms")
        if rooms:
            n = len(self.scene.rooms)
            out.append(
                {
                    "kind": "rooms",
                    "spec": rooms,
                    "found": n,
                    "held": self._count_ok(rooms, n),
                    "reason": f"{n} rooms, expected {self._count_text(rooms)}",
                }
            )
        for rt in self.spec.get("room_types", []):
            if rt.get("exact_type"):  # a plan's own room type, not the vocabulary's family
                found = [r for r in self.scene.rooms if r.type == rt["type"]]
            else:
                found = self.rooms_of_type(rt["type"]) or []
            n = len(found)
            out.append(
                {
                    "kind": "room_type",
                    "spec": rt,
                    "found": n,
                    "held": self._count_ok(rt["count"], n),
                    "reason": f"{n} {rt['type']} rooms ({', '.join(r.id for r in found)}), "
                    f"expected {self._count_text(rt['count'])}",
                }
            )
        for spec in self.spec.get("objects", []):
            objects = self.instances(spec["name"], spec.get("room"), spec)
            n = len(objects)
            where = f" in {spec.get('room_id') or spec['room']}" if spec.get("room") else ""
            out.append(
                {
                    "kind": "object",
                    "spec": spec,
                    "name": spec["name"],
                    "found": n,
                    "held": self._count_ok(spec["count"], n),
                    "reason": f"{n} found{where} ({', '.join(o.id for o in objects[:8])}), "
                    f"expected {self._count_text(spec['count'])}",
                }
            )
        return out

    def attributes(self) -> list[dict[str, Any]]:
        """Colour, material and shape specs."""
        out = []
        for spec in self.spec.get("objects", []):
            found = self.instances(spec["name"], spec.get("room"), spec)
            need = max(1, int(spec["count"].get("eq", spec["count"].get("ge", 1))))
            for key, value in (spec.get("attributes") or {}).items():
                have = []
                for o in found:
                    if key == "color":
                        fams = self.vocab.colour_words(value) or {normalise(value)}
                        seen = object_colours(o, self.vocab)
                        ok, what = bool(fams & seen), sorted(seen)
                    elif key == "material":
                        fams = self.vocab.material_words(value) or {normalise(value)}
                        seen = object_materials(o, self.vocab)
                        ok, what = bool(fams & seen), sorted(seen)
                    elif key == "shape":
                        shape = self.vocab.shapes.get(normalise(value), normalise(value))
                        ok, what = object_has_shape(o, shape, self.vocab), []
                    else:
                        ok, what = False, ["unsupported attribute"]
                    have.append((o.id, ok, what))
                n_ok = sum(1 for _, ok, _ in have if ok)
                held = bool(found) and n_ok >= min(need, len(found))
                detail = "; ".join(f"{i}: {'yes' if ok else 'no'} {w}" for i, ok, w in have[:6])
                out.append(
                    {
                        "kind": key,
                        "name": spec["name"],
                        "value": value,
                        "held": held,
                        "reason": f"{n_ok}/{len(found)} {spec['name']} {key} {value}"
                        + (f" ({detail})" if detail else ""),
                    }
                )
        return out

    def relation(self, rel: dict[str, Any]) -> Verdict:
        """One relation spec, quantified over the subject's instances."""
        kind = rel["relation"]
        if kind not in RELATIONS:
            return Verdict(False, f"unknown relation {kind!r}")
        room = rel.get("room") or self._object_room(rel["subject"])
        room_id = rel.get("room_id")
        subjects = self.instances(rel["subject"], room, self._plan_entry(rel["subject"], room_id))
        if not subjects:
            return Verdict(
                False, f"no {rel['subject']} in the scene" + (f" ({room})" if room else "")
            )
        target = rel.get("object")
        tnorm = normalise(target) if isinstance(target, str) else None
        if kind == "around":
            seats_at = self.instances(
                target or "", rel.get("room"), self._plan_entry(target or "", room_id)
            )
            if not seats_at:
                return Verdict(False, f"no {target} in the scene")
            return quantified_.around(subjects, seats_at)
        if kind in quantified_.PLACE_RELATIONS or tnorm in quantified_.WALL_WORDS:
            per = quantified_.by_place(self.scene, kind, subjects)
        elif tnorm is not None and tnorm in quantified_.OPENING_WORDS:
            per = quantified_.by_opening(self.scene, kind, subjects, tnorm)
        else:
            if not target:
                return Verdict(False, f"relation {kind!r} needs an object")
            objects = self.instances(
                target, rel.get("object_room") or room, self._plan_entry(target, room_id)
            )
            if not objects:
                return Verdict(False, f"no {target} in the scene")
            per = quantified_.by_object(self.scene, kind, subjects, objects, target)
        return quantified_.quantified(per, rel.get("quantifier", "any"), rel["subject"])

    def _plan_entry(self, name: str, room_id: str | None) -> dict[str, Any] | None:
        """The entry of ``name`` when it carries what a plan knows (ids, categories, room)."""
        entry = self.entry(name, room_id)
        keys = ("id_stem", "categories", "room_id")
        return entry if entry is not None and any(entry.get(k) for k in keys) else None

    def relations(self) -> list[dict[str, Any]]:
        """Every relation spec with its verdict."""
        out = []
        for rel in self.spec.get("relations", []):
            v = self.relation(rel)
            out.append({"kind": "relation", "spec": rel, "held": v.held, "reason": v.reason})
        return out

    def absent(self) -> list[dict[str, Any]]:
        """Names that must not appear (objects, room types, windows, doors)."""
        out = []
        for name in self.spec.get("absent", []):
            key = normalise(name)
            if key in ("window", "windows", "door", "doors"):
                ops = self.scene.windows if key.startswith("window") else self.scene.doors
                found = [op.id for op in ops]
            elif self.vocab.canonical(name) is None and self.vocab.room_canonical(name):
                found = [r.id for r in self.rooms_of_type(name) or []]
            else:
                found = [o.id for o in self.instances(name)]
            out.append(
                {
                    "kind": "absent",
                    "name": name,
                    "held": not found,
                    "reason": f"found {', '.join(found[:6])}" if found else "none found",
                }
            )
        return out

    def defining(self) -> list[dict[str, Any]]:
        """Defining furniture of every typed room, and every annotated room type exists."""
        out = []
        for room in self.scene.rooms:
            canon = self.vocab.room_type_of(room)
            rules = self.vocab.defining.get(canon or "")
            if not rules:
                continue
            missing = []
            for rule in rules:
                cats = set().union(*(self.vocab.resolve(n) for n in rule["names"]))
                n = sum(1 for o in self.scene.objects if o.room == room.id and o.labels & cats)
                if n < int(rule.get("ge", 1)):
                    missing.append(f"{'/'.join(rule['names'])} ({n} < {rule.get('ge', 1)})")
            out.append(
                {
                    "kind": "defining",
                    "room": room.id,
                    "room_type": canon,
                    "held": not missing,
                    "reason": "missing " + ", ".join(missing) if missing else "complete",
                }
            )
        for name in self.spec.get("defining", []):
            canon = self.vocab.room_canonical(name) or normalise(name)
            if not any(self.vocab.room_is(r, canon) for r in self.scene.rooms):
                out.append(
                    {
                        "kind": "defining",
                        "room": None,
                        "room_type": canon,
                        "held": False,
                        "reason": f"no {canon} room in the scene",
                    }
                )
        return out

    def validation(self) -> dict[str, Any]:
        """Whether report.json says the scene validated."""
        report = self.scene.report
        if not isinstance(report, dict):
            return {"ok": False, "reason": "no report.json"}
        unstable = [o.get("id") for o in report.get("objects", []) if not o.get("stable", True)]
        reason = (
            "ok" if report.get("ok") else f"not ok; unstable: {', '.join(map(str, unstable[:6]))}"
        )
        return {"ok": bool(report.get("ok")), "reason": reason}

    def doors(self) -> list[dict[str, Any]]:
        """For each door, the furniture overlapping the 1 m deep zone on either side."""
        return door_clearance(self.scene)

    def reachability(self) -> dict[str, Any]:
        """Share of free floor a 0.2 m robot reaches from the entrance."""
        return reachability(self.scene)

    def score(self) -> dict[str, Any]:
        """The full record of this scene (the fidelity benchmark's record)."""
        counts = self.counts()
        attributes = self.attributes()
        relations = self.relations()
        absent = self.absent()
        defining = self.defining()
        doors = self.doors()
        return {
            "id": self.spec.get("id"),
            "prompt": self.spec.get("prompt"),
            "difficulty": self.spec.get("difficulty"),
            "scene_type": self.spec.get("scene_type"),
            "folder": str(self.scene.folder),
            "scene_rooms": [
                {"id": r.id, "type": r.type, "as": self.vocab.room_type_of(r)}
                for r in self.scene.rooms
            ],
            "n_objects": len(self.scene.objects),
            "summary": {
                "count": tally(counts),
                "object_count": tally([c for c in counts if c["kind"] == "object"]),
                "room_count": tally([c for c in counts if c["kind"] != "object"]),
                "attribute": tally(attributes),
                "relation": tally(relations),
                "absent": tally(absent),
                "defining": tally(defining),
            },
            "validation": self.validation(),
            "doors_clear": all(d["clear"] for d in doors),
            "reachability": self.reachability(),
            "counts": counts,
            "attributes": attributes,
            "relations": relations,
            "absent": absent,
            "defining": defining,
            "doors": doors,
        }


def tally(rows: list[dict[str, Any]]) -> list[int]:
    """``[held, total]`` of a list of verdict rows."""
    return [sum(1 for r in rows if r["held"]), len(rows)]


_LABELLED = "_holomj_eval_labelled"


def label_objects(scene: MeasuredFolder, vocab: Vocabulary) -> None:
    """Give proxies the categories the vocabulary makes of their id's noun, and turn the view
    of work furniture used from its front (once per scene)."""
    if getattr(scene, _LABELLED, False):
        return
    for obj in scene.objects:
        if obj.from_id:  # a proxy's noun counts as what the vocabulary makes of it
            obj.labels |= {c for label in obj.labels for c in vocab.resolve(label)}
        if obj.labels & vocab.faces_away:
            obj.view_sign = -1.0
    setattr(scene, _LABELLED, True)


def score_folder(
    folder: Path, spec: dict[str, Any], vocab: Vocabulary | None = None
) -> dict[str, Any]:
    """Score one scene folder against one annotation."""
    return Scorer(Path(folder), spec, vocab).score()
