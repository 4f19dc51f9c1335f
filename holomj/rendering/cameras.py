"""Automatic cameras: an orthographic top-down view of the house, one eye-height view per room
and close-ups of receptacles. Pure geometry (metres, world frame, Z up); no MuJoCo here.

* Top: straight down, image +X to the right and +Y up; :class:`TopCamera` maps world x/y to
  pixels so the plan can be drawn on the rendered image.
* Room: in a convex corner of the room, inset from both walls, at eye height, looking at the
  mass-weighted centre of the room's furniture (the room's centre when it has none); the corner
  that sees that point, not too close, and sees the most floor wins.
* Close-up: a receptacle and what rests on it, seen from the receptacle's front (or the first
  direction that keeps the camera inside the room) 40 degrees from above, framed to fit.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, Point, Polygon
from shapely.geometry.polygon import orient

EYE_HEIGHT_M = 1.6
ROOM_FOVY_DEG = 75.0
CLOSEUP_FOVY_DEG = 45.0
CLOSEUP_ELEVATION_DEG = 40.0
CORNER_INSET_M = 0.35
TOP_MARGIN_M = 0.4
MIN_VIEW_DISTANCE_M = 1.5


@dataclass(frozen=True)
class CameraPose:
    """A camera at ``position`` looking at ``target``; orthographic ones use ``fovy`` in metres."""

    name: str
    position: tuple[float, float, float]
    target: tuple[float, float, float]
    fovy: float
    orthographic: bool = False

    def to_dict(self) -> dict[str, object]:
        """JSON-able form."""
        return {
            "position": [round(v, 4) for v in self.position],
            "target": [round(v, 4) for v in self.target],
            "fovy": round(self.fovy, 4),
            "orthographic": self.orthographic,
        }


@dataclass(frozen=True)
class TopCamera:
    """The top-down orthographic view: ``height_m`` metres of world fill the image height."""

    centre: tuple[float, float]
    height_m: float
    width_px: int
    height_px: int
    z: float

    @property
    def metres_per_pixel(self) -> float:
        """Size of one pixel on the floor."""
        return self.height_m / self.height_px

    def to_pixel(self, x: float, y: float) -> tuple[float, float]:
        """Image coordinates (column, row; origin top left) of the world point (x, y)."""
        scale = self.height_px / self.height_m
        u = self.width_px / 2 + (x - self.centre[0]) * scale
        v = self.height_px / 2 - (y - self.centre[1]) * scale
        return u, v

    def pose(self, name: str = "top") -> CameraPose:
        """The camera itself (looking straight down)."""
        cx, cy = self.centre
        return CameraPose(name, (cx, cy, self.z), (cx, cy, 0.0), self.height_m, True)

    def to_dict(self) -> dict[str, object]:
        """JSON-able form (enough to map world points onto the image)."""
        return {
            "centre": [round(v, 6) for v in self.centre],
            "height_m": round(self.height_m, 6),
            "width_px": self.width_px,
            "height_px": self.height_px,
            "metres_per_pixel": round(self.metres_per_pixel, 6),
        }


def top_camera(
    bounds: tuple[float, float, float, float], width: int, height: int, wall_height: float
) -> TopCamera:
    """A top view showing ``bounds`` (xmin, ymin, xmax, ymax) whole, with a margin."""
    xmin, ymin, xmax, ymax = bounds
    span_x = xmax - xmin + 2 * TOP_MARGIN_M
    span_y = ymax - ymin + 2 * TOP_MARGIN_M
    height_m = max(span_y, span_x * height / width)
    centre = ((xmin + xmax) / 2, (ymin + ymax) / 2)
    return TopCamera(centre, height_m, width, height, wall_height + 2.0)


@dataclass(frozen=True)
class Mass:
    """A point mass: where an object's centre of mass is and how heavy it is."""

    position: tuple[float, float, float]
    mass: float


def furniture_centre(shape: Polygon, masses: Sequence[Mass]) -> tuple[float, float, float] | None:
    """Mass-weighted centre of the masses inside ``shape``; None when there are none."""
    grown = shape.buffer(0.05)
    inside = [m for m in masses if grown.contains(Point(m.position[:2]))]
    if not inside:
        return None
    total = sum(max(m.mass, 1e-6) for m in inside)
    x, y, z = (sum(m.position[k] * max(m.mass, 1e-6) for m in inside) / total for k in range(3))
    return x, y, z


def room_camera(
    name: str,
    polygon: Sequence[Sequence[float]],
    masses: Sequence[Mass],
    wall_height: float,
    aspect: float = 4 / 3,
) -> CameraPose:
    """The eye-height camera of a room (see the module docstring).

    Corners are ranked by: seeing the target along a line inside the room, standing at least
    ``MIN_VIEW_DISTANCE_M`` from it (so the furniture fits the frame), the share of the floor in
    sight within the horizontal field of view, then distance.
    """
    shape = orient(Polygon([(float(p[0]), float(p[1])) for p in polygon]), sign=1.0)
    eye = min(EYE_HEIGHT_M, wall_height - 0.2)
    centre = furniture_centre(shape, masses)
    if centre is not None and shape.contains(Point(centre[:2])):
        target = (centre[0], centre[1], min(max(centre[2], 0.3), 1.0))
    else:
        label = shape.centroid if shape.centroid.within(shape) else shape.representative_point()
        target = (label.x, label.y, 0.6)
    half_fov = math.atan(math.tan(math.radians(ROOM_FOVY_DEG / 2)) * aspect)
    samples = _floor_samples(shape)
    grown = shape.buffer(1e-6)
    inner = shape.buffer(-0.05)
    candidates = []  # (sees the target, share of the floor in view, distance, corner)
    for corner in _corner_positions(shape):
        if not inner.contains(Point(corner)) or math.dist(corner, target[:2]) < 0.3:
            continue
        sees = LineString([corner, target[:2]]).within(grown)
        seen = _visible_share(corner, target[:2], half_fov, samples, grown)
        candidates.append((sees, seen, math.dist(corner, target[:2]), corner))
    if candidates:
        position = max(
            candidates,
            key=lambda c: (
                c[0],
                c[2] >= MIN_VIEW_DISTANCE_M,
                round(c[1], 2),
                c[2],
                -c[3][0],
                -c[3][1],
            ),
        )[3]
    else:
        spot = shape.representative_point()
        position = (spot.x, spot.y)
    if math.dist(position, target[:2]) < 0.3:
        target = (position[0] + 1.0, position[1], target[2])
    return CameraPose(name, (position[0], position[1], eye), target, ROOM_FOVY_DEG)


def _floor_samples(shape: Polygon, count: int = 200) -> np.ndarray:
    """Points on a grid inside ``shape``, about ``count`` of them (n x 2)."""
    xmin, ymin, xmax, ymax = shape.bounds
    step = max(math.sqrt(shape.area / count), 0.05)
    xs = np.arange(xmin + step / 2, xmax, step)
    ys = np.arange(ymin + step / 2, ymax, step)
    grid = np.array([(x, y) for y in ys for x in xs]) if len(xs) and len(ys) else np.zeros((0, 2))
    if len(grid) == 0:
        return grid
    return grid[shapely.contains_xy(shape, grid[:, 0], grid[:, 1])]


def _visible_share(
    position: tuple[float, float],
    target: tuple[float, float],
    half_fov: float,
    samples: np.ndarray,
    shape: Polygon,
) -> float:
    """Share of ``samples`` inside the horizontal field of view and in sight from ``position``."""
    if len(samples) == 0:
        return 0.0
    offsets = samples - np.asarray(position)
    heading = math.atan2(target[1] - position[1], target[0] - position[0])
    angles = np.arctan2(offsets[:, 1], offsets[:, 0]) - heading
    angles = (angles + math.pi) % (2 * math.pi) - math.pi
    in_view = samples[np.abs(angles) <= half_fov]
    if len(in_view) == 0:
        return 0.0
    starts = np.repeat(np.asarray([position]), len(in_view), axis=0)
    lines = shapely.linestrings(np.stack([starts, in_view], axis=1))
    return float(np.count_nonzero(shapely.within(lines, shape))) / len(samples)


def _corner_positions(shape: Polygon) -> list[tuple[float, float]]:
    """Points inset from each convex corner of a counter-clockwise polygon along its bisector."""
    points = list(shape.exterior.coords)[:-1]
    result = []
    for i, (x, y) in enumerate(points):
        px, py = points[i - 1]
        nx, ny = points[(i + 1) % len(points)]
        a = _unit(x - px, y - py)
        b = _unit(nx - x, ny - y)
        if a is None or b is None or a[0] * b[1] - a[1] * b[0] <= 1e-9:
            continue  # reflex or straight corner: no room to stand in
        # inward normals of the two edges (left of the direction of travel)
        n1, n2 = (-a[1], a[0]), (-b[1], b[0])
        bisector = _unit(n1[0] + n2[0], n1[1] + n2[1])
        if bisector is None:
            continue
        # distance along the bisector that keeps CORNER_INSET_M from both walls
        along = CORNER_INSET_M / max(bisector[0] * n1[0] + bisector[1] * n1[1], 0.2)
        result.append((x + bisector[0] * along, y + bisector[1] * along))
    return result


def _unit(dx: float, dy: float) -> tuple[float, float] | None:
    length = math.hypot(dx, dy)
    return None if length < 1e-9 else (dx / length, dy / length)


def closeup_camera(
    name: str,
    centre: tuple[float, float, float],
    radius: float,
    front_deg: float,
    room: Polygon | None,
) -> CameraPose:
    """A camera framing the sphere (``centre``, ``radius``) from the front and above.

    ``front_deg`` is the receptacle's front direction (yaw); other directions are tried, in
    growing turns from the front, when the camera would stand outside ``room`` or look at the
    object through one of its walls.
    """
    half = math.radians(CLOSEUP_FOVY_DEG / 2)
    distance = max(radius / math.sin(half) * 1.1, 0.5)
    elevation = math.radians(CLOSEUP_ELEVATION_DEG)
    inner = room.buffer(-0.05) if room is not None else None
    grown = room.buffer(1e-6) if room is not None else None
    turns = (0, 30, -30, 60, -60, 90, -90, 120, -120, 150, -150, 180)
    for scale in (1.0, 0.75, 0.55):
        for turn in turns:
            azimuth = math.radians(front_deg + turn)
            reach = distance * scale * math.cos(elevation)
            position = (
                centre[0] + reach * math.cos(azimuth),
                centre[1] + reach * math.sin(azimuth),
                centre[2] + distance * scale * math.sin(elevation),
            )
            if (
                inner is None
                or grown is None
                or (
                    inner.contains(Point(position[:2]))
                    and LineString([position[:2], centre[:2]]).within(grown)
                )
            ):
                return CameraPose(name, position, centre, CLOSEUP_FOVY_DEG)
    # nowhere beside it fits: look straight down from above (slightly tilted for an up vector)
    position = (centre[0] - 0.05, centre[1], centre[2] + distance)
    return CameraPose(name, position, centre, CLOSEUP_FOVY_DEG)
