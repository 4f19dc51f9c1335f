"""What an instruction asks for, as :func:`holomj.refinement.instruction.read_instruction` reads
it: items to add, remove or move, and the notes on what could not be used."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Literal

Action = Literal["add", "add_on", "remove", "move"]


@dataclass
class Item:
    """One thing the instruction asks for.

    ``relations``: (edit relation kind, target) with target None (a place), ``"item:<key>"``
    (another item of the instruction) or a scene object id. ``targets``: the scene objects a
    ``remove`` or ``move`` is about. ``on``: the receptacle of an ``add_on``."""

    key: str
    action: Action
    kind: str
    description: str
    category: str | None
    categories: tuple[str, ...]
    placement: str
    quantity: int
    room: str | None
    relations: list[tuple[str, str | None]] = field(default_factory=list)
    targets: list[str] = field(default_factory=list)
    on: str | None = None
    phrase: str = ""
    clause: int = 0

    @property
    def slug(self) -> str:
        """``floor lamp`` -> ``floor_lamp``."""
        return re.sub(r"[^a-z0-9]+", "_", self.kind.lower()).strip("_") or "object"

    @property
    def stem(self) -> str:
        """The id stem of the objects refine adds for it: ``living_room.refine.armchair``."""
        return f"{self.room or 'scene'}.refine.{self.key}"

    def to_json(self) -> dict[str, object]:
        """JSON-able form (for refine.json)."""
        return {
            "key": self.key,
            "action": self.action,
            "kind": self.kind,
            "description": self.description,
            "category": self.category,
            "placement": self.placement,
            "quantity": self.quantity,
            "room": self.room,
            "relations": [list(r) for r in self.relations],
            "targets": list(self.targets),
            "on": self.on,
            "phrase": self.phrase,
        }


@dataclass
class Instruction:
    """The items an instruction asks for, and what could not be used."""

    text: str
    items: list[Item]
    notes: list[str] = field(default_factory=list)

    def item(self, key: str) -> Item | None:
        """The item ``key``."""
        return next((i for i in self.items if i.key == key), None)

    @property
    def rooms(self) -> list[str]:
        """The rooms the items are in (in order, once)."""
        return list(dict.fromkeys(i.room for i in self.items if i.room))

    def to_json(self) -> dict[str, object]:
        """JSON-able form (for refine.json)."""
        return {
            "text": self.text,
            "items": [i.to_json() for i in self.items],
            "notes": list(self.notes),
        }
