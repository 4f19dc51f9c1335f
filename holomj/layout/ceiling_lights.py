"""Point lights under a room's ceiling (:func:`ceiling_lights`)."""

from __future__ import annotations

from collections.abc import Sequence

from shapely.geometry import Point, Polygon

from holomj.spec.scene import Light, Room

BIG_ROOM_M2 = 25.0
LIGHT_BELOW_CEILING_M = 0.3


def ceiling_lights(rooms: Sequence[Room], wall_height: float) -> list[Light]:
    """Point lights under the ceiling: one per room at its centroid, a 2 x 2 grid in rooms over
    25 m². Total energy grows with the area (0.2 + 0.012 per m², at most 0.8), shared by the
    room's lights."""
    lights: list[Light] = []
    z = max(wall_height - LIGHT_BELOW_CEILING_M, 0.5)
    for room in rooms:
        poly = Polygon(room.polygon)
        total = min(0.8, 0.2 + 0.012 * poly.area)
        if poly.area > BIG_ROOM_M2:
            x0, y0, x1, y1 = poly.bounds
            points = [
                (x0 + (x1 - x0) * fx, y0 + (y1 - y0) * fy)
                for fy in (0.25, 0.75)
                for fx in (0.25, 0.75)
            ]
            points = [_inside(poly, p) for p in points]
        else:
            points = [_inside(poly, (poly.centroid.x, poly.centroid.y))]
        for k, (x, y) in enumerate(points):
            lights.append(
                Light(
                    id=f"light_{room.id}" if len(points) == 1 else f"light_{room.id}_{k}",
                    kind="point",
                    position=(round(x, 4), round(y, 4), round(z, 4)),
                    energy=round(total / len(points), 4),
                    color=(1.0, 0.96, 0.9),
                )
            )
    return lights


def _inside(poly: Polygon, point: tuple[float, float]) -> tuple[float, float]:
    p = Point(point)
    if poly.contains(p):
        return point
    q = poly.representative_point()
    return (q.x, q.y)
