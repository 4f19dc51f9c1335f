"""The greedy solver's search space: the cells the placed objects take (:class:`Occupancy`) and the
free poses of one object ranked by the constraints they satisfy (:class:`CandidateFinder`), a
few well apart kept to try.
"""

from __future__ import annotations

import numpy as np

from holomj.layout import geometry as geo
from holomj.layout.constraints import PLACE_KINDS
from holomj.layout.cpsat_soft_rules import NEAR_PREFERRED_M  # the tie-break of both solvers
from holomj.layout.geometry import Pose
from holomj.layout.place_relations import place_holds
from holomj.layout.room_problem import PreparedRoom


class Occupancy:
    """The cells taken by placed objects' collision boxes, and the poses."""

    def __init__(self, prep: PreparedRoom) -> None:
        self.prep = prep
        self.mask = np.zeros_like(prep.wall_block)
        self.poses: dict[int, Pose] = {}

    def _cells(self, i: int, pose: Pose) -> tuple[slice, slice]:
        prep = self.prep
        x, y, k = pose
        hx, hy = prep.coll_half(i, k)
        return (
            slice(x - hx - prep.i0, x + hx - prep.i0),
            slice(y - hy - prep.j0, y + hy - prep.j0),
        )

    def place(self, i: int, pose: Pose) -> None:
        """Mark object ``i`` at ``pose``."""
        self.mask[self._cells(i, pose)] = True
        self.poses[i] = pose

    def remove(self, i: int) -> Pose:
        """Unmark object ``i`` (collision boxes never share cells) and return its pose."""
        pose = self.poses.pop(i)
        self.mask[self._cells(i, pose)] = False
        return pose

    def metres(self) -> dict[int, tuple[float, float, int]]:
        """Poses in metres."""
        g = self.prep.grid
        return {i: (x * g, y * g, k) for i, (x, y, k) in self.poses.items()}

    def rects(self, extra: dict[int, Pose] | None = None) -> list[tuple[float, ...]]:
        """Footprints (metres) of the placed objects plus ``extra``."""
        g = self.prep.grid
        poses = dict(self.poses)
        poses.update(extra or {})
        return [self.prep.footprint(i, x * g, y * g, k) for i, (x, y, k) in poses.items()]


def _strip_ranges(
    x: np.ndarray, y: np.ndarray, k: int, hx: int, hy: int, length: int
) -> tuple[np.ndarray, ...]:
    """Cell ranges (units) of the strip ``length`` deep in front of a collision box, 2 wide."""
    if k == 0:
        return x + hx, y - 1, x + hx + length, y + 1
    if k == 1:
        return x - 1, y + hy, x + 1, y + hy + length
    if k == 2:
        return x - hx - length, y - 1, x - hx, y + 1
    return x - 1, y - hy - length, x + 1, y - hy


class CandidateFinder:
    """Valid poses of one object given the occupancy, with constraint scores."""

    def __init__(self, prep: PreparedRoom, rng: np.random.Generator) -> None:
        self.prep = prep
        self.rng = rng
        self.walls_sat = geo.SummedArea(prep.wall_block)
        self.front_len = prep.units_up(prep.settings.front_clearance_m)
        self.by_object: dict[int, list] = {i.index: [] for i in prep.items}
        self.by_target: dict[int, list] = {i.index: [] for i in prep.items}
        for c in prep.constraints:
            self.by_object[prep.index[c.object]].append(c)
            if c.target is not None:
                self.by_target[prep.index[c.target]].append(c)

    def blocked_sat(self, i: int, occ: np.ndarray | None) -> geo.SummedArea:
        """Summed-area table of the cells object ``i`` may not cover."""
        prep = self.prep
        blocked = prep.wall_block | prep.door_block
        if prep.items[i].tall:
            blocked = blocked | prep.windows_block(i)
        if occ is not None:
            blocked = blocked | occ
        return geo.SummedArea(blocked)

    def valid_mask(
        self, i: int, k: int, occ: np.ndarray | None, sat: geo.SummedArea | None = None
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """Grid-unit centres ``(X, Y)`` and the mask of valid ones at yaw index ``k``."""
        prep = self.prep
        hx, hy = prep.coll_half(i, k)
        nx, ny = prep.raster.nx, prep.raster.ny
        xs = np.arange(prep.i0 + hx, prep.i0 + nx - hx + 1)
        ys = np.arange(prep.j0 + hy, prep.j0 + ny - hy + 1)
        if xs.size == 0 or ys.size == 0:
            return None
        x, y = np.meshgrid(xs, ys, indexing="ij")
        sat = sat if sat is not None else self.blocked_sat(i, occ)
        i0, j0 = prep.i0, prep.j0
        ok = sat.count(x - hx - i0, y - hy - j0, x + hx - i0, y + hy - j0) == 0
        if self.front_len > 0:
            a0, b0, a1, b1 = _strip_ranges(x, y, k, hx, hy, self.front_len)
            ok &= self.walls_sat.count(a0 - i0, b0 - j0, a1 - i0, b1 - j0) == 0
        return x, y, ok

    def scores(self, i: int, k: int, x: np.ndarray, y: np.ndarray, occ: Occupancy) -> np.ndarray:
        """Weight of the constraints satisfied at each centre with the objects placed so far."""
        prep = self.prep
        g = prep.grid
        item = prep.items[i]
        xm, ym = x * g, y * g
        score = np.zeros(x.shape)
        has_global = False
        for c in self.by_object[i]:
            if c.kind == "edge":
                has_global = True
                score += c.weight * geo.edge_holds(
                    xm, ym, k, item.size, prep.walls, prep.thresholds.edge_tolerance
                )
            elif c.kind == "middle":
                has_global = True
                score += c.weight * self.middle_ok(i, k, x, y)
            elif c.kind in PLACE_KINDS:
                has_global = True
                score += c.weight * place_holds(
                    c.kind, xm, ym, k, item.size, prep.anchors, prep.thresholds.edge_tolerance
                )
            else:
                j = prep.index[c.target]
                if j not in occ.poses:
                    continue
                xt, yt, kt = occ.poses[j]
                score += self._relation(
                    c, (xm, ym, k, item.size), (xt * g, yt * g, kt, prep.items[j].size)
                )
        for c in self.by_target[i]:
            a = prep.index[c.object]
            if a not in occ.poses:
                continue
            xa, ya, ka = occ.poses[a]
            score += self._relation(
                c, (xa * g, ya * g, ka, prep.items[a].size), (xm, ym, k, item.size)
            )
        if not has_global:
            # Holodeck's default: an object without a global constraint prefers a wall.
            score += 0.01 * geo.edge_holds(
                xm, ym, k, item.size, prep.walls, prep.thresholds.edge_tolerance
            )
        return score

    def _relation(self, c, a: tuple, t: tuple) -> np.ndarray:
        """Weight where the relation holds, plus a tie-break for near: within 0.4 m is best."""
        xa, ya, ka, size_a = a
        xt, yt, kt, size_t = t
        holds = geo.relation_holds(
            c.kind, xa, ya, ka, size_a, xt, yt, kt, size_t, self.prep.thresholds
        )
        score = c.weight * holds
        if c.kind == "near":
            hxa, hya = geo.half_extents(size_a[0], size_a[1], ka)
            hxt, hyt = geo.half_extents(size_t[0], size_t[1], kt)
            gx = np.maximum(np.abs(xa - xt) - hxa - hxt, 0.0)
            gy = np.maximum(np.abs(ya - yt) - hya - hyt, 0.0)
            near = self.prep.thresholds.near
            excess = np.maximum(gx + gy - NEAR_PREFERRED_M, 0.0)
            closeness = np.clip(1.0 - excess / max(near - NEAR_PREFERRED_M, 1e-6), 0.0, 1.0)
            score = score + 0.01 * holds * closeness
        return score

    def middle_ok(self, i: int, k: int, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """The footprint grown by the middle gap stays inside the room (raster test)."""
        prep = self.prep
        item = prep.items[i]
        hx, hy = geo.half_extents(item.width, item.depth, k)
        gap = prep.thresholds.middle_gap
        mx, my = prep.units_up(hx + gap), prep.units_up(hy + gap)
        i0, j0 = prep.i0, prep.j0
        return self.walls_sat.count(x - mx - i0, y - my - j0, x + mx - i0, y + my - j0) == 0

    def ranked(self, i: int, occ: Occupancy, limit: int = 400) -> list[tuple[float, Pose]]:
        """The best ``limit`` valid poses of object ``i``, best first."""
        found: list[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]] = []
        sat = self.blocked_sat(i, occ.mask)
        for k in range(4):
            res = self.valid_mask(i, k, occ.mask, sat)
            if res is None:
                continue
            x, y, ok = res
            if not ok.any():
                continue
            xv, yv = x[ok], y[ok]
            sc = self.scores(i, k, xv, yv, occ) + self.rng.random(xv.shape) * 1e-4
            found.append((sc, xv, yv, np.full(xv.shape, k)))
        if not found:
            return []
        sc = np.concatenate([f[0] for f in found])
        xs = np.concatenate([f[1] for f in found])
        ys = np.concatenate([f[2] for f in found])
        ks = np.concatenate([f[3] for f in found])
        top = np.argpartition(-sc, limit)[:limit] if sc.size > limit else np.arange(sc.size)
        top = top[np.argsort(-sc[top], kind="stable")]
        return [(float(sc[t]), (int(xs[t]), int(ys[t]), int(ks[t]))) for t in top]

    def fits_empty(self, i: int) -> bool:
        """Whether object ``i`` has any valid pose in the empty room."""
        sat = self.blocked_sat(i, None)
        for k in range(4):
            res = self.valid_mask(i, k, None, sat)
            if res is not None and res[2].any():
                return True
        return False


def diverse_poses(ranked: list[tuple[float, Pose]], count: int, min_units: int) -> list[Pose]:
    """Up to ``count`` of the ``ranked`` poses, best first, each another yaw or at least
    ``min_units`` (Manhattan) from those kept."""
    chosen: list[Pose] = []
    for _, pose in ranked:
        if all(
            pose[2] != c[2] or abs(pose[0] - c[0]) + abs(pose[1] - c[1]) >= min_units
            for c in chosen
        ):
            chosen.append(pose)
            if len(chosen) == count:
                break
    return chosen
