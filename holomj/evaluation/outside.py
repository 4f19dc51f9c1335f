"""Objects outside their room: a footprint corner more than 5 cm beyond the room's polygon (the
room objects.json gives the object; any room when it gives none). Wall surfaces lie on or
inside the polygon (exterior walls grow outwards, interior walls are centred on it), so
furniture against a wall and objects hung on it stay inside."""

from __future__ import annotations

from typing import Any

from shapely.geometry import Point
from shapely.ops import unary_union

from holomj.evaluation.folder import MeasuredFolder

OUTSIDE_M = 0.05


def outside_rooms(scene: MeasuredFolder) -> tuple[list[dict[str, Any]], int]:
    """(the objects outside their room, with how far and where their centre is; the number
    of objects checked)."""
    if not scene.rooms:
        return [], 0
    anywhere = unary_union([r.poly for r in scene.rooms])
    out = []
    for obj in scene.objects:
        room = scene.room_by_id.get(obj.room or "")
        area = room.poly if room is not None else anywhere
        beyond = max(area.distance(Point(c)) for c in obj.fp.exterior.coords)
        if beyond <= OUTSIDE_M:
            continue
        centre = Point(obj.center)
        holder = next((r.id for r in scene.rooms if r.poly.contains(centre)), None)
        where = f"centre in {holder}" if holder else "centre outside every room"
        out.append(
            {
                "id": obj.id,
                "room": obj.room,
                "outside_m": round(beyond, 3),
                "centre_in": holder,
                "reason": f"{beyond:.2f} m beyond {obj.room or 'the rooms'} ({where})",
            }
        )
    return out, len(scene.objects)
