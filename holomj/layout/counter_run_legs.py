"""A counter run's legs as composite objects: the room's problem with each leg one object, held in
shape by the run's constraints (:func:`composite_problem`), and the solved legs split back into
their modules along their walls (:func:`split_legs`), checked with the modules' real widths
(:func:`real_problem`).

See :mod:`holomj.layout.counter_runs` for the whole method.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from typing import Any

from holomj.layout import geometry as geo
from holomj.layout.composite import HeaviestConstraints, composite_room
from holomj.layout.constraints import GLOBAL_KINDS, Constraint, ConstraintKind
from holomj.layout.counter_run_arrangements import (
    EPS,
    ISLAND_WEIGHT,
    MAX_ORDER_COMBOS,
    RUN_WEIGHT,
    Arrangement,
)
from holomj.layout.counter_run_walls import Span, WallSpace, chain_layout, chain_walls, stretch
from holomj.layout.place_relations import opening_gap
from holomj.layout.room_problem import LayoutObject, RoomProblem
from holomj.layout.solve import Placement


def composite_problem(
    problem: RoomProblem, arr: Arrangement, legs: list[str], island: str | None
) -> RoomProblem:
    """The problem with each leg of ``arr`` as one object, the constraints moved onto the legs
    and the shape's own constraints added."""
    owner = {m.id: legs[k] for k, seq in enumerate(arr.legs) for m in seq}
    # A leg that abuts a corner leg is declared shorter at that end by the clearance (which
    # becomes contact) and two grid steps (the solver's grid rounds footprints up); the split
    # lays it against the corner leg, and the check of the split catches any clash.
    shrink = problem.settings.clearance_m + 2 * problem.settings.grid_m
    objects: list[LayoutObject] = []
    for obj in problem.objects:
        if obj.id not in owner:
            objects.append(obj)
            continue
        k = legs.index(owner[obj.id])
        if any(o.id == legs[k] for o in objects):
            continue
        seq = arr.legs[k]
        objects.append(
            LayoutObject(
                id=legs[k],
                width=arr.leg_length(k) - arr.joined(k) * shrink,
                depth=arr.leg_depth(k),
                height=arr.leg_height(k),
                unit="m",
                priority=max(m.priority for m in seq),
            )
        )
    kept = HeaviestConstraints()
    for c in problem.all_constraints().constraints:
        subject = owner.get(c.object, c.object)
        target = owner.get(c.target, c.target) if c.target is not None else None
        if c.object in owner and c.kind in GLOBAL_KINDS and c.kind in _RUN_OWN_PLACES:
            continue  # the run places its legs itself
        if target is not None and (subject == target or (c.object in owner and c.target in owner)):
            continue  # between modules of the run: kept by the run
        kept.add(c.model_copy(update={"object": subject, "target": target}))
    source = f"counter run: {arr.shape}"

    def shape_rule(
        obj: str, kind: ConstraintKind, target: str | None = None, weight: float = RUN_WEIGHT
    ) -> None:
        kept.add(Constraint(object=obj, kind=kind, target=target, weight=weight, source=source))

    for leg in legs:
        shape_rule(leg, "edge")
    if arr.shape == "galley":
        shape_rule(legs[0], "face_to", legs[1])
        shape_rule(legs[1], "face_to", legs[0])
    for j, corner_leg in enumerate(arr.owners):  # junction j joins legs j and j + 1
        other = j + 1 if corner_leg == j else j
        shape_rule(legs[corner_leg], "corner")
        shape_rule(legs[other], "adjacent_to", legs[corner_leg])
        shape_rule(legs[other], "in_front_of", legs[corner_leg])
    if island is not None and arr.shape != "galley" and any(o.id == island for o in objects):
        main = max(range(len(legs)), key=lambda k: (arr.leg_length(k), -k))
        shape_rule(island, "in_front_of", legs[main], ISLAND_WEIGHT)
    return composite_room(problem, objects, kept.all())


# Place constraints a run module gives up to the run (the rest follow the module's leg).
_RUN_OWN_PLACES = frozenset({"edge", "middle", "corner", "centre"})


def real_problem(problem: RoomProblem, arr: Arrangement) -> RoomProblem:
    """``problem`` with every run module at its real width (a layout object may be widened
    for a wall object hung above it): what the modules' footprints are checked as."""
    widths = {m.id: m.width for seq in arr.legs for m in seq}
    objects = []
    for obj in problem.objects:
        if obj.id in widths:
            _, depth, height = problem.object_size_m(obj)
            obj = obj.model_copy(
                update={"width": widths[obj.id], "depth": depth, "height": height, "unit": "m"}
            )
        objects.append(obj)
    return problem.model_copy(update={"objects": objects})


# --------------------------------------------------------------------------- splitting


def _placements(wall: geo.WallSegment, spans: Sequence[Span]) -> dict[str, Placement]:
    """Modules at their stretches along ``wall``, backs on it, fronts into the room."""
    k = wall.facing_k
    assert k is not None  # legs stand only at walls along x or y (edge_holds)
    (ax, ay), (tx, ty), (nx, ny) = wall.a, wall.tangent, wall.inward
    out = {}
    for module, a0, a1 in spans:
        mid = (a0 + a1) / 2
        out[module.id] = Placement(
            x=round(ax + tx * mid + nx * module.depth / 2, 6),
            y=round(ay + ty * mid + ny * module.depth / 2, 6),
            yaw_deg=90.0 * k,
            width=module.width,
            depth=module.depth,
        )
    return out


def _leg_wall(space: WallSpace, p: Placement, tolerance: float) -> int | None:
    """The wall a solved leg has its back to (within ``tolerance``), if any."""
    k = geo.yaw_index(p.yaw_deg)
    fx, fy = geo.FRONT[k]
    back = (p.x - fx * p.depth / 2, p.y - fy * p.depth / 2)
    best: tuple[float, int] | None = None
    for i, wall in enumerate(space.walls):
        if wall.facing_k != k:
            continue
        along, off = wall.locate(back)
        on_wall = -EPS <= along <= wall.length + EPS and -EPS <= off <= tolerance + EPS
        if on_wall and (best is None or off < best[0]):
            best = (off, i)
    return None if best is None else best[1]


def _sink_gap(space: WallSpace, placements: Mapping[str, Placement], sinks: set[str]) -> float:
    """How far the ``sinks`` are from the nearest window (0 without sinks or windows)."""
    windows = space.prep.anchors.windows
    out = 0.0
    for module_id, p in placements.items():
        if not windows or module_id not in sinks:
            continue
        k = geo.yaw_index(p.yaw_deg)
        out += min(float(opening_gap(p.x, p.y, k, (p.width, p.depth), w)) for w in windows)
    return out


def split_legs(
    arr: Arrangement, solved: list[Placement], space: WallSpace, problem: RoomProblem
) -> tuple[dict[str, Placement], dict[str, Any]] | str:
    """The modules of each solved leg laid side by side (a straight leg where the solver put
    it, an L's or a U's legs from their corners: :func:`chain_layout`) in the cheapest orders
    that bring the sink nearest a window, and the record's fields; or why the solved legs do
    not make the shape."""
    s = problem.settings
    walls = space.walls
    where = [_leg_wall(space, p, s.edge_tolerance_m + s.grid_m) for p in solved]
    if None in where:
        return f"leg {where.index(None)} does not stand with its back to a wall"
    ws = tuple(w for w in where if w is not None)
    best: tuple[float, list[list[Span]], float | None] | None = None
    combos = list(itertools.islice(itertools.product(*arr.options), MAX_ORDER_COMBOS))
    sinks = {m.id for leg in arr.legs for m in leg if m.category == "sink_counter"}
    if arr.shape in ("one_wall", "galley"):
        if arr.shape == "galley":
            wa, wb = walls[ws[0]], walls[ws[1]]
            if wa.facing_k is None or wb.facing_k != (wa.facing_k + 2) % 4:
                return "the galley's legs are not on opposite walls"
        starts = [walls[w].locate((p.x, p.y))[0] - p.width / 2 for w, p in zip(ws, solved)]
        for orders in combos:
            for flips in itertools.product((False, True), repeat=len(ws)):
                legs = [
                    stretch(start + arr.leg_length(k), -1, order)
                    if flip
                    else stretch(start, 1, order)
                    for k, (start, order, flip) in enumerate(zip(starts, orders, flips))
                ]
                score = _sink_gap(space, _all_placements(walls, ws, legs), sinks)
                if best is None or score < best[0] - EPS:
                    best = (score, legs, None)
    else:
        if ws not in chain_walls(space, len(ws)):
            return "the legs are not on consecutive walls that meet at corners"
        why = "no order of the legs fits"
        for orders in combos:
            laid = chain_layout(space, arr, ws, orders)
            if isinstance(laid, str):
                why = laid
                continue
            legs = [list(leg) for leg in laid.legs]
            score = _sink_gap(space, _all_placements(walls, ws, legs), sinks)
            if best is None or score < best[0] - EPS:
                best = (score, legs, laid.filler)
        if best is None:
            return why
    assert best is not None
    _, legs, filler = best
    placements = _all_placements(walls, ws, legs)
    if arr.shape == "galley":
        sides = [[placements[m.id] for m, _, _ in leg] for leg in legs]
        if not _face_each_other(sides[0], sides[1]):
            return "the galley's legs do not face each other"
    roles = [
        "run"
        if arr.shape == "one_wall"
        else "side"
        if arr.shape == "galley"
        else "middle"
        if arr.shape == "U" and k == 1
        else "corner"
        if k in arr.owners
        else "arm"
        for k in range(len(legs))
    ]
    extra: dict[str, Any] = {
        "legs": [
            {
                "role": role,
                "modules": [m.id for m, _, _ in leg],
                "wall": [[round(v, 3) for v in walls[w].a], [round(v, 3) for v in walls[w].b]],
                "length_m": round(max(a1 for _, _, a1 in leg) - min(a0 for _, a0, _ in leg), 3),
            }
            for role, leg, w in zip(roles, legs, ws)
        ],
        "penalty": arr.penalty,
    }
    if arr.shape == "U":
        extra["corner_legs"] = sorted(set(arr.owners))
        extra["filler_m"] = round(max(filler or 0.0, 0.0), 3)
    return placements, extra


def _all_placements(
    walls: Sequence[geo.WallSegment], ws: Sequence[int], legs: Sequence[Sequence[Span]]
) -> dict[str, Placement]:
    out: dict[str, Placement] = {}
    for w, leg in zip(ws, legs):
        out.update(_placements(walls[w], leg))
    return out


def _face_each_other(a: Sequence[Placement], b: Sequence[Placement]) -> bool:
    """Whether two legs on opposite walls overlap along them (they face each other)."""
    ra = [geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth) for p in a]
    rb = [geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth) for p in b]
    axis = 1 if geo.yaw_index(a[0].yaw_deg) % 2 == 0 else 0  # the direction along the walls
    lo_a, hi_a = min(r[axis] for r in ra), max(r[axis + 2] for r in ra)
    lo_b, hi_b = min(r[axis] for r in rb), max(r[axis + 2] for r in rb)
    return min(hi_a, hi_b) - max(lo_a, lo_b) > EPS
