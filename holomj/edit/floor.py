"""One floor object placed among others that stay exactly where they are.

The layout solver lays out a whole room; an edit must not move what it does not touch, so a new
(or moved, or replaced) floor object is placed by a search over free floor poses instead: every
centre on the layout's 5 cm grid and every quarter turn (or the one yaw asked), in the room's
layout polygon (inset from the walls as :mod:`holomj.compose.room_furnishing` does it). The
checks are the layout's hard rules, in metres, against the real footprints of everything in the
room (turned by any yaw):

* inside the room, at least 5 cm from every object it would meet in height (floor furniture;
  wall and ceiling objects hanging lower than its top);
* out of every door's keep-out zone and leaf sweep, and, when taller than a window's sill, out of
  the zone in front of it; its front 0.3 m clear of the walls;
* the way between the room's doors stays open (a 0.6 m walker; only when it was open before),
  no free floor is cut off from the doors (at most 0.1 m², for a 0.3 m robot), and the object
  can be reached.

Candidates are ranked by the weight of the relations they satisfy (judged by the layout's own
predicates, :class:`holomj.layout.room_problem.PreparedRoom`), then by closeness to the
relation targets (or to a wished-for spot, or to the walls), then by grid order, so the search
is deterministic; the first that passes every check wins.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

from holomj.edit.floor_rules import (
    bounded_extent,
    constraint_holds,
    layout_openings,
    turned_half_extents,
)
from holomj.edit.floor_walk import FloorWalk
from holomj.edit.footprints import (
    FLOOR_Z_M,
    Thing,
    corners,
    footprint,
    in_room,
    object_size,
    object_yaw,
)
from holomj.edit.state import Refused
from holomj.layout import geometry as geo
from holomj.layout.constraints import OPENING_KINDS, Constraint
from holomj.layout.furniture_rules import DOOR_CLEARANCE_M, WALKER_RADIUS_M
from holomj.layout.geometry import LAYOUT_MARGIN_M
from holomj.layout.room_problem import (
    LayoutObject,
    LayoutSettings,
    PreparedRoom,
    RoomProblem,
)
from holomj.library.store import AssetLibrary
from holomj.spec.decor import DECOR_CATEGORIES
from holomj.spec.scene import SceneSpec

STEP_M = 0.05
CLEARANCE_M = 0.05
FRONT_CLEARANCE_M = 0.3
MAX_TRIES = 1500
NEW = "new"  # the layout name of the object being placed


@dataclass(frozen=True)
class Wish:
    """A relation the placed object should satisfy: a layout constraint kind, the target's
    scene id (None for places), its weight and the words it came from."""

    kind: str
    target: str | None = None
    weight: float = 10.0
    source: str = ""


@dataclass
class FloorSpot:
    """Where the object goes, and the verdict on every wish there."""

    x: float
    y: float
    yaw_deg: float
    verdicts: list[dict[str, object]] = field(default_factory=list)

    @property
    def satisfied(self) -> int:
        """How many wishes hold."""
        return sum(bool(v["holds"]) for v in self.verdicts)


@dataclass(frozen=True)
class Blocker:
    """Something on the floor that is not a scene object (a robot's base): its outline, its
    height and its room (None: any)."""

    id: str
    polygon: Polygon
    height: float
    room: str | None = None


class RoomFloor:
    """A room's floor with everything in it held still (``exclude``: ids left out, such as the
    object being moved and what rests on it)."""

    def __init__(
        self,
        scene: SceneSpec,
        room_id: str,
        library: AssetLibrary,
        exclude: frozenset[str] = frozenset(),
        blockers: Sequence[Blocker] = (),
    ) -> None:
        self.scene = scene
        self.room = scene.room(room_id)
        inset = scene.wall_thickness / 2 + LAYOUT_MARGIN_M
        shape = Polygon(self.room.polygon).buffer(-inset, join_style="mitre")
        if not isinstance(shape, Polygon) or shape.is_empty:
            raise Refused(f"room {room_id!r} has no usable floor")
        self.polygon = orient(shape, sign=1.0)
        self.things: list[Thing] = []
        for obj in scene.objects:
            if obj.id in exclude or obj.support is not None or not in_room(scene, obj, room_id):
                continue
            meta = library.get(obj.asset).meta if obj.asset in library else None
            if meta is not None and meta.category in DECOR_CATEGORIES:
                continue  # rugs lie under furniture
            depth, width, height = object_size(obj, library)
            yaw = object_yaw(obj)
            x, y, z = obj.position
            self.things.append(
                Thing(
                    obj.id, footprint(x, y, yaw, width, depth), z, z + height, x, y, yaw,
                    width, depth, z < FLOOR_Z_M,
                )
            )  # fmt: skip
        for blocker in blockers:
            if blocker.room not in (None, room_id):
                continue
            c = blocker.polygon.centroid
            x0, y0, x1, y1 = blocker.polygon.bounds
            self.things.append(
                Thing(
                    blocker.id, blocker.polygon, 0.0, blocker.height, c.x, c.y, 0.0,
                    y1 - y0, x1 - x0, True,
                )
            )  # fmt: skip
        self.ids = {t.id for t in self.things}
        self._walk: FloorWalk | None = None

    # ------------------------------------------------------------------ the layout's view

    def prepared(self, width: float, depth: float, height: float, wishes: Sequence[Wish]):
        """The layout problem of this room with the object to place (``NEW``) and its wishes,
        prepared (door zones, window zones, anchors, the walk checker)."""
        ring = list(self.polygon.exterior.coords)[:-1]
        doors, windows = layout_openings(self.scene, self.room.id, ring)
        objects = [
            LayoutObject(
                id=f"o{k}",
                width=bounded_extent(t.width),
                depth=bounded_extent(t.depth),
                height=bounded_extent(t.top - t.bottom),
            )
            for k, t in enumerate(self.things)
        ]
        objects.append(LayoutObject(id=NEW, width=width, depth=depth, height=height))
        alias = {t.id: f"o{k}" for k, t in enumerate(self.things)}
        constraints = []
        for wish in wishes:
            if wish.target is not None and wish.target not in alias:
                raise Refused(f"{wish.target!r} is not in room {self.room.id!r}")
            target = alias.get(wish.target) if wish.target is not None else None
            constraints.append(
                Constraint(
                    object=NEW, target=target, weight=wish.weight, source=wish.source or None,
                    kind=wish.kind,  # type: ignore[arg-type]  # str from the tables; pydantic checks it
                )
            )  # fmt: skip
        problem = RoomProblem(
            room_id="room",
            polygon=[(round(x, 6), round(y, 6)) for x, y in ring],
            size_unit="m",
            doors=doors,
            windows=windows,
            objects=objects,
            constraints=constraints,
            settings=LayoutSettings(
                walker_radius_m=WALKER_RADIUS_M, door_clearance_m=DOOR_CLEARANCE_M
            ),
        )
        return PreparedRoom(problem)

    # ------------------------------------------------------------------ checks

    def _rules(
        self, prep: PreparedRoom, xs: np.ndarray, ys: np.ndarray, yaw: float, size3: tuple
    ) -> list[tuple[str, np.ndarray]]:
        """Every hard rule as (what breaks it, mask of candidates that keep it), in order."""
        width, depth, height = size3
        polys = shapely.polygons(corners(xs, ys, yaw, width, depth))
        room = self.polygon.buffer(1e-7)
        rules = [(f"outside room {self.room.id!r}", np.asarray(shapely.covers(room, polys)))]
        for thing in self.things:
            if thing.bottom >= height or thing.top <= 0.0:
                continue
            gap = np.asarray(shapely.distance(thing.polygon, polys))
            rules.append((f"overlaps {thing.id}", gap > 1e-9))
            rules.append(
                (f"closer than {CLEARANCE_M:g} m to {thing.id}", gap >= CLEARANCE_M - 1e-6)
            )
        doors = [d for d in self.scene.doors if self.room.id in d.rooms]
        for door, zone in zip(doors, prep.door_zones):
            area = np.asarray(shapely.area(shapely.intersection(zone, polys)))
            rules.append((f"in the keep-out zone of door {door.id}", area <= 1e-9))
        windows = [w for w in self.scene.windows if self.room.id in w.rooms]
        for window, zone in zip(windows, prep.window_zones):
            if height <= window.base_height:
                continue
            area = np.asarray(shapely.area(shapely.intersection(zone, polys)))
            rules.append(
                (f"taller than the sill of window {window.id} and in front of it", area <= 1e-9)
            )
        fx, fy = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
        sx, sy = xs + fx * depth / 2, ys + fy * depth / 2
        segs = shapely.linestrings(
            np.stack(
                [np.stack([sx, sy], -1), np.stack([sx + fx * FRONT_CLEARANCE_M,
                                                   sy + fy * FRONT_CLEARANCE_M], -1)], 1
            )
        )  # fmt: skip
        rules.append(
            (
                f"faces a wall closer than {FRONT_CLEARANCE_M:g} m",
                np.asarray(shapely.covers(self.polygon.buffer(geo.EPS), segs)),
            )
        )
        return rules

    def problems(
        self, x: float, y: float, yaw_deg: float, size3: tuple[float, float, float]
    ) -> list[str]:
        """The hard rules a pose breaks, in words (empty: it may go there)."""
        width, depth, height = size3
        prep = self.prepared(width, depth, height, [])
        xs, ys = np.array([x]), np.array([y])
        out = [what for what, ok in self._rules(prep, xs, ys, yaw_deg, size3) if not ok[0]]
        if not out:
            out = self._walk_problems(prep, footprint(x, y, yaw_deg, width, depth))
        return out

    def _walk_problems(self, prep: PreparedRoom, poly: Polygon) -> list[str]:
        walk = self._walk
        if walk is None or walk.prep is not prep:
            walk = self._walk = FloorWalk(
                self.polygon, [t.polygon.bounds for t in self.things if t.on_floor], prep
            )
        return walk.problems(poly)

    # ------------------------------------------------------------------ search

    def place(
        self,
        size3: tuple[float, float, float],
        wishes: Sequence[Wish],
        *,
        yaw_deg: float | None = None,
        near: tuple[float, float] | None = None,
        within: float | None = None,
    ) -> FloorSpot:
        """The best free pose for an object of ``size3`` = (width, depth, height), see the
        module doc; ``near``/``within``: only candidates within that distance of a point,
        nearest first. Refused with the commonest broken rule when there is none."""
        width, depth, height = size3
        prep = self.prepared(width, depth, height, wishes)
        new = prep.index[NEW]
        poses = {
            prep.index[f"o{k}"]: (t.x, t.y, geo.yaw_index(t.yaw_deg))
            for k, t in enumerate(self.things)
        }
        minx, miny, maxx, maxy = self.polygon.bounds
        yaws = [yaw_deg] if yaw_deg is not None else [0.0, 90.0, 180.0, 270.0]
        rows: list[tuple] = []
        broken: Counter[str] = Counter()
        for yaw in yaws:
            k = geo.yaw_index(yaw)
            hx, hy = turned_half_extents(width, depth, yaw)
            gx = np.arange(
                math.ceil((minx + hx) / STEP_M - 1e-9), math.floor((maxx - hx) / STEP_M + 1e-9) + 1
            )
            gy = np.arange(
                math.ceil((miny + hy) / STEP_M - 1e-9), math.floor((maxy - hy) / STEP_M + 1e-9) + 1
            )
            if len(gx) == 0 or len(gy) == 0:
                continue
            xs, ys = (a.ravel() * STEP_M for a in np.meshgrid(gx, gy, indexing="ij"))
            xs, ys = np.round(xs, 6), np.round(ys, 6)
            if near is not None and within is not None:
                keep = np.hypot(xs - near[0], ys - near[1]) <= within + 1e-9
                xs, ys = xs[keep], ys[keep]
            ok = np.ones(len(xs), dtype=bool)
            for what, mask in self._rules(prep, xs, ys, yaw, size3):
                broken[what] += int((ok & ~mask).sum())
                ok &= mask
            xs, ys = xs[ok], ys[ok]
            if len(xs) == 0:
                continue
            score = np.zeros(len(xs))
            for c in prep.constraints:
                score += c.weight * constraint_holds(prep, c, xs, ys, k, new, poses)
            second = self._secondary(prep, xs, ys, yaw, size3, wishes, near)
            rows.extend(
                (-round(float(s), 6), round(float(d), 6), k, float(x), float(y), yaw)
                for s, d, x, y in zip(score, second, xs, ys)
            )
        rows.sort()
        for row in rows[:MAX_TRIES]:
            _, _, _, x, y, yaw = row
            problems = self._walk_problems(prep, footprint(x, y, yaw, width, depth))
            if problems:
                broken[problems[0]] += 1
                continue
            return FloorSpot(x, y, yaw % 360.0, self._verdicts(prep, new, poses, x, y, yaw))
        what = f"{width:.2f} x {depth:.2f} m"
        if not broken:
            raise Refused(f"no floor in room {self.room.id!r} for a {what} footprint")
        commonest = ", ".join(w for w, _ in broken.most_common(2))
        raise Refused(f"no free floor in room {self.room.id!r} for a {what} object ({commonest})")

    def _secondary(self, prep, xs, ys, yaw, size3, wishes, near) -> np.ndarray:
        """Among candidates that satisfy as much: the nearest to the wished-for spot, else to
        the relation targets (beside them for "next to" and "near"), to the windows or doors
        a place relation names, else to the walls."""
        if near is not None:
            return np.hypot(xs - near[0], ys - near[1])
        out = np.zeros(len(xs))
        things = {t.id: t for t in self.things}
        used = False
        for wish in wishes:
            if wish.target is not None and wish.target in things:
                t = things[wish.target]
                dx, dy = xs - t.x, ys - t.y
                if wish.kind in ("adjacent_to", "near"):  # beside it, not behind or before it
                    c, s = math.cos(math.radians(t.yaw_deg)), math.sin(math.radians(t.yaw_deg))
                    out += np.abs(dx * c + dy * s) + 0.25 * np.abs(-dx * s + dy * c)
                else:
                    out += np.hypot(dx, dy)
                used = True
            elif wish.kind in OPENING_KINDS:
                spans = prep.anchors.doors if "door" in wish.kind else prep.anchors.windows
                if spans:
                    out += np.min([np.hypot(xs - o.center[0], ys - o.center[1]) for o in spans], 0)
                    used = True
        if used or any(w.kind == "middle" for w in wishes):
            return out
        width, depth, _ = size3
        polys = shapely.polygons(corners(xs, ys, yaw, width, depth))
        return np.asarray(shapely.distance(self.polygon.exterior, polys))

    def _verdicts(self, prep, new, poses, x, y, yaw) -> list[dict[str, object]]:
        at = {**poses, new: (x, y, geo.yaw_index(yaw))}
        names = {f"o{k}": t.id for k, t in enumerate(self.things)}
        out = []
        for c in prep.constraints:
            holds, detail = prep.evaluate(c, at)
            out.append(
                {
                    "kind": c.kind,
                    "target": names.get(c.target) if c.target else None,
                    "weight": c.weight,
                    "holds": bool(holds),
                    "detail": detail,
                    "source": c.source,
                }
            )
        return out

    def verdicts(
        self, x: float, y: float, yaw_deg: float, size3: tuple, wishes: Sequence[Wish]
    ) -> list[dict[str, object]]:
        """The verdict on every wish for an object of ``size3`` at a given pose."""
        prep = self.prepared(size3[0], size3[1], size3[2], wishes)
        poses = {
            prep.index[f"o{k}"]: (t.x, t.y, geo.yaw_index(t.yaw_deg))
            for k, t in enumerate(self.things)
        }
        return self._verdicts(prep, prep.index[NEW], poses, x, y, yaw_deg)
