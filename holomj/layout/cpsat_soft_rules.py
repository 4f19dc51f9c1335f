"""The soft constraints of the room's CP-SAT model (:mod:`holomj.layout.solver_cpsat`): one
literal ``s_c`` per constraint, which enforces (through ``OnlyEnforceIf`` on ``s_c`` and the
yaw literals) a conservative integer form of the geometric test of
:mod:`holomj.layout.geometry`: sizes are rounded the safe way, so that whatever the model calls
satisfied passes the post-check.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import cast

from ortools.sat.python import cp_model

from holomj.layout import geometry as geo
from holomj.layout.geometry import CellRect
from holomj.layout.place_relations import (
    ADJACENT_GAP_M,
    BY_DOOR_GAP_M,
    BY_WINDOW_GAP_M,
    CENTRE_REACH_M,
    CORNER_TOLERANCE_M,
    under_window_overlap,
)
from holomj.layout.room_problem import PreparedRoom

NEAR_PREFERRED_M = 0.4


class SoftRules:
    """The encodings of the soft constraints, mixed into the room's model (which creates the
    variables declared here)."""

    prep: PreparedRoom
    m: cp_model.CpModel
    p: list[cp_model.IntVar]  # presence per object
    o: list[list[cp_model.IntVar]]  # yaw literals per object
    x: list[cp_model.IntVar]
    y: list[cp_model.IntVar]
    s: list[cp_model.IntVar]  # one literal per constraint
    near_gaps: list[tuple[cp_model.IntVar, cp_model.LinearExpr, int]]  # s, excess, cap
    wall_rects: list[CellRect]  # the walls' cells, in grid units (the hard part's)

    def _fixed(
        self, rects: Sequence[CellRect], tag: str
    ) -> tuple[list[cp_model.IntervalVar], list[cp_model.IntervalVar]]:
        """Fixed intervals along x and y for each rectangle (cells in grid units)."""
        xs, ys = [], []
        for n, (a, b, c, d) in enumerate(rects):
            xs.append(self.m.new_fixed_size_interval_var(a, c - a, f"{tag}x{n}"))
            ys.append(self.m.new_fixed_size_interval_var(b, d - b, f"{tag}y{n}"))
        return xs, ys

    def half(self, i: int, axis: int, mode: str) -> cp_model.LinearExpr:
        """Object i's half size along world ``axis`` (0 x, 1 y), in units, as a yaw expression."""
        fn = self.prep.true_half_down if mode == "down" else self.prep.true_half_up
        # a sum of four terms, never the start value 0
        return cast(cp_model.LinearExpr, sum(self.o[i][k] * fn(i, k)[axis] for k in range(4)))

    def build_soft(self) -> None:
        prep = self.prep
        for n, c in enumerate(prep.constraints):
            s = self.m.new_bool_var(f"s{n}")
            self.s.append(s)
            a = prep.index[c.object]
            self.m.add_implication(s, self.p[a])
            t = prep.index[c.target] if c.target is not None else None
            if t is not None:
                self.m.add_implication(s, self.p[t])
            if c.kind == "edge":
                self._edge(s, a)
            elif c.kind == "middle":
                self._middle(s, a)
            elif c.kind == "corner":
                self._corner(s, a)
            elif c.kind == "centre":
                cx, cy = prep.anchors.centre
                for var, mid in ((self.x[a], cx), (self.y[a], cy)):
                    self.m.add(var >= prep.units_up(mid - CENTRE_REACH_M)).only_enforce_if(s)
                    self.m.add(var <= prep.units_down(mid + CENTRE_REACH_M)).only_enforce_if(s)
            elif c.kind == "under_window":
                self._under_window(s, a)
            elif c.kind in ("by_window", "by_door"):
                self._by_opening(s, a, c.kind)
            elif c.kind in ("facing_window", "facing_door"):
                self._facing_opening(s, a, c.kind)
            elif t is not None:
                self._relation(s, c.kind, a, t)
            else:
                raise ValueError(f"relation {c.kind} without a target")

    def _lit(self, name: str) -> cp_model.IntVar:
        return self.m.new_bool_var(name)

    def _edge(self, s: cp_model.IntVar, a: int) -> None:
        prep = self.prep
        item = prep.items[a]
        tol, hd = prep.thresholds.edge_tolerance, item.depth / 2
        options = []
        for w, wall in enumerate(prep.walls):
            k = wall.facing_k
            if k is None:
                continue
            e = self._lit(f"e{len(self.s)}_{w}")
            options.append(e)
            self.m.add_implication(e, self.o[a][k])
            (ax, ay), (bx, by) = wall.a, wall.b
            if k in (0, 2):
                lo, hi = min(ay, by), max(ay, by)
                self.m.add(self.y[a] >= prep.units_up(lo)).only_enforce_if(e)
                self.m.add(self.y[a] <= prep.units_down(hi)).only_enforce_if(e)
                if k == 0:
                    self.m.add(self.x[a] <= prep.units_down(ax + tol + hd)).only_enforce_if(e)
                    self.m.add(self.x[a] >= prep.units_up(ax + hd)).only_enforce_if(e)
                else:
                    self.m.add(self.x[a] >= prep.units_up(ax - tol - hd)).only_enforce_if(e)
                    self.m.add(self.x[a] <= prep.units_down(ax - hd)).only_enforce_if(e)
            else:
                lo, hi = min(ax, bx), max(ax, bx)
                self.m.add(self.x[a] >= prep.units_up(lo)).only_enforce_if(e)
                self.m.add(self.x[a] <= prep.units_down(hi)).only_enforce_if(e)
                if k == 1:
                    self.m.add(self.y[a] <= prep.units_down(ay + tol + hd)).only_enforce_if(e)
                    self.m.add(self.y[a] >= prep.units_up(ay + hd)).only_enforce_if(e)
                else:
                    self.m.add(self.y[a] >= prep.units_up(ay - tol - hd)).only_enforce_if(e)
                    self.m.add(self.y[a] <= prep.units_down(ay - hd)).only_enforce_if(e)
        if options:
            self.m.add_bool_or(options).only_enforce_if(s)
        else:
            self.m.add(s == 0)

    def _middle(self, s: cp_model.IntVar, a: int) -> None:
        prep = self.prep
        item = prep.items[a]
        gap = prep.thresholds.middle_gap
        fx, fy = self._fixed(self.wall_rects, f"mw{len(self.s)}_")
        for k in (0, 1):
            hx, hy = geo.half_extents(item.width, item.depth, k)
            mx, my = prep.units_up(hx + gap), prep.units_up(hy + gap)
            lit = self._lit(f"m{len(self.s)}_{k}")
            # lit == s AND (o_k or o_k+2)
            self.m.add(lit <= s)
            self.m.add(lit <= self.o[a][k] + self.o[a][k + 2])
            self.m.add(lit >= s + self.o[a][k] + self.o[a][k + 2] - 1)
            fx.append(
                self.m.new_optional_fixed_size_interval_var(
                    self.x[a] - mx, 2 * mx, lit, f"mx{len(self.s)}_{k}"
                )
            )
            fy.append(
                self.m.new_optional_fixed_size_interval_var(
                    self.y[a] - my, 2 * my, lit, f"my{len(self.s)}_{k}"
                )
            )
        self.m.add_no_overlap_2d(fx, fy)

    def _corner(self, s: cp_model.IntVar, a: int) -> None:
        """Both walls of some convex corner within the edge tolerance of the footprint."""
        prep, m = self.prep, self.m
        tol = min(prep.thresholds.edge_tolerance, CORNER_TOLERANCE_M)
        options = []
        for n, c in enumerate(prep.anchors.corners):
            lit = self._lit(f"c{len(self.s)}_{n}")
            options.append(lit)
            hx, hy = self.half(a, 0, "down"), self.half(a, 1, "down")
            # conservative: the true half size is at least the rounded-down one
            if c.sx > 0:
                m.add(self.x[a] - hx <= prep.units_down(c.x + tol)).only_enforce_if(lit)
            else:
                m.add(self.x[a] + hx >= prep.units_up(c.x - tol)).only_enforce_if(lit)
            if c.sy > 0:
                m.add(self.y[a] - hy <= prep.units_down(c.y + tol)).only_enforce_if(lit)
            else:
                m.add(self.y[a] + hy >= prep.units_up(c.y - tol)).only_enforce_if(lit)
        self._any(s, options)

    def _under_window(self, s: cp_model.IntVar, a: int) -> None:
        """Back to a window's wall within the edge tolerance, overlapping the window's span."""
        prep, m = self.prep, self.m
        item = prep.items[a]
        tol, hd, hw = prep.thresholds.edge_tolerance, item.depth / 2, item.width / 2
        options = []
        for n, w in enumerate(prep.anchors.windows):
            k = w.wall.facing_k
            if k is None:
                continue
            lit = self._lit(f"u{len(self.s)}_{n}")
            options.append(lit)
            m.add_implication(lit, self.o[a][k])
            need = under_window_overlap(item.width, w)
            x0, x1, y0, y1 = w.box
            wall_x, wall_y = w.wall.a
            if k in (0, 2):  # a wall along y: the window spans y, the back is at x
                lo, hi, normal, line = y0, y1, self.x[a], wall_x
                along = self.y[a]
            else:
                lo, hi, normal, line = x0, x1, self.y[a], wall_y
                along = self.x[a]
            m.add(along >= prep.units_up(lo + need - hw)).only_enforce_if(lit)
            m.add(along <= prep.units_down(hi - need + hw)).only_enforce_if(lit)
            if k in (0, 1):  # the room is on the + side of the wall line
                m.add(normal >= prep.units_up(line + hd)).only_enforce_if(lit)
                m.add(normal <= prep.units_down(line + tol + hd)).only_enforce_if(lit)
            else:
                m.add(normal <= prep.units_down(line - hd)).only_enforce_if(lit)
                m.add(normal >= prep.units_up(line - tol - hd)).only_enforce_if(lit)
        self._any(s, options)

    def _by_opening(self, s: cp_model.IntVar, a: int, kind: str) -> None:
        """The footprint within the kind's gap of a window's or door's opening (as an L1 gap on
        the grid, which bounds the Euclidean one)."""
        prep, m = self.prep, self.m
        anchors = prep.anchors
        openings = anchors.windows if kind == "by_window" else anchors.doors
        limit = BY_WINDOW_GAP_M if kind == "by_window" else BY_DOOR_GAP_M
        big = prep.raster.nx + prep.raster.ny + 10
        options = []
        for n, opening in enumerate(openings):
            lit = self._lit(f"b{len(self.s)}_{n}")
            options.append(lit)
            (cx, cy), (ox, oy) = opening.center, opening.half
            g = prep.grid
            # centre rounded to the grid: shrink the opening by half a cell to stay conservative
            cxu, cyu = round(cx / g), round(cy / g)
            sx = self.half(a, 0, "down") + prep.units_down(max(ox - g / 2, 0.0))
            sy = self.half(a, 1, "down") + prep.units_down(max(oy - g / 2, 0.0))
            gx = m.new_int_var(0, big, f"b{len(self.s)}_{n}gx")
            gy = m.new_int_var(0, big, f"b{len(self.s)}_{n}gy")
            m.add(gx >= self.x[a] - cxu - sx).only_enforce_if(lit)
            m.add(gx >= cxu - self.x[a] - sx).only_enforce_if(lit)
            m.add(gy >= self.y[a] - cyu - sy).only_enforce_if(lit)
            m.add(gy >= cyu - self.y[a] - sy).only_enforce_if(lit)
            m.add(gx + gy <= prep.units_down(limit)).only_enforce_if(lit)
        self._any(s, options)

    def _facing_opening(self, s: cp_model.IntVar, a: int, kind: str) -> None:
        """The front ray from the centre meets a window's or door's opening (the opening shrunk
        to whole grid units, so that what the model accepts holds)."""
        prep, m = self.prep, self.m
        anchors = prep.anchors
        openings = anchors.windows if kind == "facing_window" else anchors.doors
        options = []
        for n, opening in enumerate(openings):
            (x0, x1, y0, y1), (ox, oy) = opening.box, opening.half
            (cx, cy) = opening.center
            for k, (fx, fy) in enumerate(geo.FRONT):
                lit = self._lit(f"fo{len(self.s)}_{n}_{k}")
                options.append(lit)
                m.add_implication(lit, self.o[a][k])
                if fx != 0:
                    m.add(self.y[a] >= prep.units_up(y0)).only_enforce_if(lit)
                    m.add(self.y[a] <= prep.units_down(y1)).only_enforce_if(lit)
                    if fx > 0:
                        m.add(self.x[a] <= prep.units_down(cx + ox)).only_enforce_if(lit)
                    else:
                        m.add(self.x[a] >= prep.units_up(cx - ox)).only_enforce_if(lit)
                else:
                    m.add(self.x[a] >= prep.units_up(x0)).only_enforce_if(lit)
                    m.add(self.x[a] <= prep.units_down(x1)).only_enforce_if(lit)
                    if fy > 0:
                        m.add(self.y[a] <= prep.units_down(cy + oy)).only_enforce_if(lit)
                    else:
                        m.add(self.y[a] >= prep.units_up(cy - oy)).only_enforce_if(lit)
        self._any(s, options)

    def _any(self, s: cp_model.IntVar, options: list[cp_model.IntVar]) -> None:
        """``s`` only when one of the options holds (never when there is none)."""
        if options:
            self.m.add_bool_or(options).only_enforce_if(s)
        else:
            self.m.add(s == 0)

    def _relation(self, s: cp_model.IntVar, kind: str, a: int, t: int) -> None:
        """Object ``a`` in relation ``kind`` to object ``t``, enforced when ``s`` holds."""
        if kind in ("near", "adjacent_to"):
            self._near(s, kind, a, t)
        elif kind == "far":
            self._far(s, a, t)
        elif kind == "center_aligned":
            self._center_aligned(s, a, t)
        elif kind in ("face_same_as", "face_opposite_to"):
            shift = 0 if kind == "face_same_as" else 2
            for k in range(4):
                self.m.add(self.o[a][k] == self.o[t][(k + shift) % 4]).only_enforce_if(s)
        elif kind == "face_to":
            self._face_to(s, a, t)
        else:
            self._by_target_front(s, kind, a, t)

    def _offsets(self, a: int, t: int) -> tuple[cp_model.LinearExpr, cp_model.LinearExpr, str]:
        """``a``'s centre less ``t``'s, in units along x and y, and the tag of the relation's
        own variables."""
        return self.x[a] - self.x[t], self.y[a] - self.y[t], f"r{len(self.s)}"

    def _near(self, s: cp_model.IntVar, kind: str, a: int, t: int) -> None:
        prep, m = self.prep, self.m
        th = prep.thresholds
        dx, dy, tag = self._offsets(a, t)
        big = prep.raster.nx + prep.raster.ny + 10
        gx = m.new_int_var(0, big, f"{tag}gx")
        gy = m.new_int_var(0, big, f"{tag}gy")
        sx = self.half(a, 0, "down") + self.half(t, 0, "down")
        sy = self.half(a, 1, "down") + self.half(t, 1, "down")
        m.add(gx >= dx - sx).only_enforce_if(s)
        m.add(gx >= -dx - sx).only_enforce_if(s)
        m.add(gy >= dy - sy).only_enforce_if(s)
        m.add(gy >= -dy - sy).only_enforce_if(s)
        limit = th.near_raw_gap if kind == "near" else ADJACENT_GAP_M
        m.add(gx + gy <= prep.units_down(limit)).only_enforce_if(s)
        if kind == "adjacent_to":
            return
        # Tie-break: among layouts satisfying the same constraints, prefer gaps of at most
        # NEAR_PREFERRED_M (legroom between a sofa and its coffee table, say).
        self.near_gaps.append(
            (s, gx + gy - prep.units_down(NEAR_PREFERRED_M), prep.units_down(th.near_raw_gap))
        )

    def _far(self, s: cp_model.IntVar, a: int, t: int) -> None:
        prep, m = self.prep, self.m
        dx, dy, tag = self._offsets(a, t)
        f = prep.units_up(prep.thresholds.far_raw_gap)
        sx = self.half(a, 0, "up") + self.half(t, 0, "up")
        sy = self.half(a, 1, "up") + self.half(t, 1, "up")
        lits = [self._lit(f"{tag}f{q}") for q in range(4)]
        m.add(dx >= f + sx).only_enforce_if(lits[0])
        m.add(-dx >= f + sx).only_enforce_if(lits[1])
        m.add(dy >= f + sy).only_enforce_if(lits[2])
        m.add(-dy >= f + sy).only_enforce_if(lits[3])
        m.add_bool_or(lits).only_enforce_if(s)

    def _center_aligned(self, s: cp_model.IntVar, a: int, t: int) -> None:
        m = self.m
        dx, dy, tag = self._offsets(a, t)
        # strictly closer than the tolerance (Holodeck's test): one unit less when it falls on
        # the grid, so on the 5 cm grid that is exact alignment
        tol = self.prep.units_up(self.prep.thresholds.align_tolerance) - 1
        lx, ly = self._lit(f"{tag}ax"), self._lit(f"{tag}ay")
        m.add(dx <= tol).only_enforce_if(lx)
        m.add(-dx <= tol).only_enforce_if(lx)
        m.add(dy <= tol).only_enforce_if(ly)
        m.add(-dy <= tol).only_enforce_if(ly)
        m.add_bool_or([lx, ly]).only_enforce_if(s)

    def _face_to(self, s: cp_model.IntVar, a: int, t: int) -> None:
        m = self.m
        dx, dy, _ = self._offsets(a, t)
        for k, (fx, fy) in enumerate(geo.FRONT):
            fwd = -(dx * fx + dy * fy)
            lat = -(dx * -fy + dy * fx)
            t_lat = self.half(t, 1 if fx != 0 else 0, "down")
            on = [s, self.o[a][k]]
            m.add(fwd >= 0).only_enforce_if(on)
            m.add(lat <= t_lat).only_enforce_if(on)
            m.add(-lat <= t_lat).only_enforce_if(on)

    def _by_target_front(self, s: cp_model.IntVar, kind: str, a: int, t: int) -> None:
        """In front of, behind, left of, right of or on a side of ``t``, in ``t``'s frame."""
        prep, m = self.prep, self.m
        dx, dy, tag = self._offsets(a, t)
        item_t = prep.items[t]
        hd_t, hw_t = item_t.depth / 2, item_t.width / 2
        for k, (fx, fy) in enumerate(geo.FRONT):
            along = dx * fx + dy * fy
            lat = dx * -fy + dy * fx
            on = [s, self.o[t][k]]
            if kind in ("in_front_of", "behind"):
                a_along = self.half(a, 0 if fx != 0 else 1, "down")
                reach = prep.units_down(prep.thresholds.in_front_max_gap + hd_t)
                signed = along if kind == "in_front_of" else -along
                m.add(signed >= prep.units_up(hd_t)).only_enforce_if(on)
                m.add(signed <= reach + a_along).only_enforce_if(on)
                m.add(lat <= prep.units_down(hw_t)).only_enforce_if(on)
                m.add(-lat <= prep.units_down(hw_t)).only_enforce_if(on)
                continue
            band = prep.units_down(hd_t)
            m.add(along <= band).only_enforce_if(on)
            m.add(-along <= band).only_enforce_if(on)
            side = prep.units_up(hw_t)
            if kind == "left_of":
                m.add(lat >= side).only_enforce_if(on)
            elif kind == "right_of":
                m.add(-lat >= side).only_enforce_if(on)
            elif kind == "side_of":
                left = self._lit(f"{tag}l{k}")
                m.add(lat >= side).only_enforce_if([*on, left])
                m.add(-lat >= side).only_enforce_if([*on, ~left])
            else:
                raise ValueError(f"unknown relation {kind}")
