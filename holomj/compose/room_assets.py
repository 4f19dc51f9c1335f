"""One asset per planned instance of a room: what generate's retrieval stage chooses.

The chooser (:class:`holomj.retrieval.assets.AssetRetriever` in generate, a plain ranking in
tests) is asked once per planned object; an object it cannot serve is recorded with the reason,
never dropped silently. Each room draws from its own stage generator.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from holomj.errors import HolomjError
from holomj.library.store import AssetLibrary
from holomj.retrieval.chooser import AssetChooser
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanObject, PlanRoom


def description_of(obj: PlanObject) -> str:
    """The text retrieval matches: the description, else the name."""
    return obj.description.strip() or obj.name


@dataclass
class RoomAssets:
    """The assets retrieved for a room's floor and wall instances (instance name -> asset id)."""

    room_id: str
    floor: dict[str, str] = field(default_factory=dict)
    wall: dict[str, str] = field(default_factory=dict)
    ceiling: dict[str, str] = field(default_factory=dict)
    picks: list[dict[str, Any]] = field(default_factory=list)
    failed: list[dict[str, str]] = field(default_factory=list)


def retrieve_room(
    plan_room: PlanRoom, library: AssetLibrary, chooser: AssetChooser, seed: int
) -> RoomAssets:
    """One asset per floor and wall instance of ``plan_room``; failures are recorded."""
    out = RoomAssets(plan_room.id)
    rng = stage_rng(seed, "retrieve", plan_room.id)
    out.floor = _retrieve(plan_room, "floor", chooser, rng, out)
    out.wall = _retrieve(plan_room, "wall", chooser, rng, out)
    out.ceiling = _retrieve(plan_room, "ceiling", chooser, rng, out)
    return out


def _retrieve(
    plan_room: PlanRoom,
    placement: str,
    chooser: AssetChooser,
    rng: np.random.Generator,
    out: RoomAssets,
) -> dict[str, str]:
    """Instance name -> asset id for the room's objects of one placement."""
    chosen: dict[str, str] = {}
    for obj in plan_room.objects:
        if obj.placement != placement:
            continue
        try:
            picks = chooser.choose(
                description_of(obj),
                quantity=obj.quantity,
                variance=obj.variance,
                rng=rng,
                size=obj.size,
                placement=placement,
                category=obj.category,
            )
        except HolomjError as err:
            for instance in obj.instances():
                out.failed.append(
                    {"object": instance, "stage": "retrieve", "reason": err.one_line()}
                )
            continue
        for instance, pick in zip(obj.instances(), picks):
            chosen[instance] = pick.asset_id
            record: dict[str, Any] = {
                "room": plan_room.id,
                "instance": instance,
                "asset": pick.asset_id,
            }
            for key in ("category", "score", "visual", "text", "size"):
                value = getattr(pick, key, None)
                if value is not None:
                    record[key] = round(value, 4) if isinstance(value, float) else value
            record.update(on_demand_record(pick))
            out.picks.append(record)
    return chosen


def on_demand_record(pick: Any) -> dict[str, Any]:
    """What a pick says about the attributes asked and honoured, and how (library match,
    synthesised, proxy...); empty for a pick that does not say (a plain ranking)."""
    if getattr(pick, "attributes_asked", None) is None:
        return {}
    record = {
        "attributes_asked": pick.attributes_asked,
        "attributes_honoured": pick.attributes_honoured or {},
        "how": pick.how,
        "proxy": bool(pick.proxy),
    }
    if getattr(pick, "attributes_how", None) is not None:  # per part: "brass on the handles"
        record["attributes_how"] = pick.attributes_how
    return record
