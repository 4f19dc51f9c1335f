"""Benchmark: floor-object layout, constraints satisfied and time, CP-SAT and greedy.

Cases: the 6 x 5 m living room fixture (10 objects, 36 constraints in Holodeck's text format;
goal: at least 34 satisfied, as Holodeck's DFS did, in under 1 s with no overlaps) and generated
rooms with 5, 10, 20 and 30 objects carrying Holodeck-like constraints (goal for 30: under 5 s).
Writes JSON::

    python scripts/bench_layout.py --out bench_results/layout.json [--repeats 3]
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from holomj.layout.room_problem import problem_from_data
from holomj.layout.solve import solve_room

FIXTURE = Path(__file__).resolve().parent.parent / "tests" / "fixtures" / "layout_living_room.json"

# Groups of objects with Holodeck-style constraint lines; "{x}" names the group's instances.
# Sizes: width, depth, height in cm.
GROUPS: list[list[tuple[str, tuple[int, int, int], str]]] = [
    [
        ("sofa", (200, 90, 85), "edge"),
        (
            "coffee table",
            (110, 60, 45),
            "middle | near, {sofa} | in front of, {sofa} | center aligned, {sofa} "
            "| face to, {sofa}",
        ),
        (
            "armchair",
            (80, 80, 90),
            "middle | near, {coffee table} | side of, {coffee table} | face to, {coffee table}",
        ),
        ("side table", (50, 50, 55), "edge | near, {sofa} | side of, {sofa}"),
    ],
    [
        ("tv stand", (150, 45, 55), "edge | far, {sofa} | face to, {sofa}"),
        ("bookshelf", (90, 35, 180), "edge | far, {tv stand}"),
        ("plant", (45, 45, 110), "edge | near, {bookshelf} | side of, {bookshelf}"),
    ],
    [
        ("desk", (120, 60, 75), "edge"),
        (
            "office chair",
            (60, 60, 100),
            "middle | in front of, {desk} | near, {desk} | center aligned, {desk} "
            "| face to, {desk}",
        ),
        ("floor lamp", (40, 40, 160), "edge | near, {desk}"),
    ],
    [
        ("dining table", (160, 90, 75), "middle"),
        (
            "dining chair",
            (45, 50, 90),
            "middle | near, {dining table} | side of, {dining table} | face to, {dining table}",
        ),
        (
            "dining chair",
            (45, 50, 90),
            "middle | near, {dining table} | side of, {dining table} | face to, {dining table}",
        ),
        ("cabinet", (100, 45, 90), "edge | far, {dining table}"),
    ],
]


def generate_problem(n_objects: int, seed: int = 0) -> dict:
    """A rectangular room sized to fit ``n_objects`` objects with Holodeck-like constraints."""
    rng = np.random.default_rng(seed)
    objects: list[dict] = []
    lines: list[str] = []
    counters: dict[str, int] = {}
    while len(objects) < n_objects:
        for group in GROUPS:
            names: dict[str, str] = {}
            for kind, (w, d, h), rule in group:
                if len(objects) >= n_objects:
                    break
                index = counters.get(kind, 0)
                counters[kind] = index + 1
                name = f"{kind}-{index}"
                names.setdefault(kind, name)
                jitter = 1.0 + 0.1 * (rng.random() - 0.5)
                objects.append(
                    {
                        "id": name.replace(" ", "_"),
                        "width": round(w * jitter),
                        "depth": round(d * jitter),
                        "height": h,
                    }
                )
                parts = [p.strip() for p in rule.split("|")]
                kept = []
                for part in parts:
                    targets = [t for t in GROUP_KINDS if "{" + t + "}" in part]
                    if any(t not in names for t in targets):
                        continue  # its target was cut off by n_objects
                    kept.append(_fill(part, names))
                lines.append(" | ".join([name, *kept]))
    area = sum(o["width"] * o["depth"] for o in objects) / 1e4
    room_area = max(area * 3.2, 9.0)
    width = math.ceil(math.sqrt(room_area * 1.25) * 2) / 2
    depth = math.ceil(room_area / width * 2) / 2
    doors = [{"id": "door-0", "position": [width, round(depth * 0.8, 2)], "width": 0.9}]
    if n_objects >= 20:
        doors.append({"id": "door-1", "position": [round(width * 0.2, 2), 0.0], "width": 0.9})
    return {
        "room_id": f"generated_{n_objects}",
        "polygon": [[0, 0], [width, 0], [width, depth], [0, depth]],
        "size_unit": "cm",
        "doors": doors,
        "windows": [
            {
                "id": "window-0",
                "position": [round(width / 2, 2), depth],
                "width": 1.5,
                "sill_height": 0.9,
            }
        ],
        "objects": objects,
        "constraints_text": "\n".join(lines) + "\n",
    }


GROUP_KINDS = sorted({kind for group in GROUPS for kind, _, _ in group}, key=len, reverse=True)


def _fill(part: str, names: dict[str, str]) -> str:
    for kind in GROUP_KINDS:
        if kind in names:
            part = part.replace("{" + kind + "}", names[kind])
    return part


def run_case(name: str, data: dict, solver: str, time_limit: float, repeats: int) -> dict:
    problem = problem_from_data(data, name)
    times, results = [], []
    for rep in range(repeats):
        start = time.perf_counter()
        result = solve_room(
            problem, solver=solver, time_limit_s=time_limit, rng=np.random.default_rng(rep)
        )
        times.append(time.perf_counter() - start)
        results.append(result)
    best = results[0]
    return {
        "case": name,
        "solver": solver,
        "objects": len(problem.objects),
        "placed": len(best.placements),
        "unplaced": [u.id for u in best.unplaced],
        "satisfied": [r.satisfied for r in results],
        "total": best.total,
        "time_s_median": round(statistics.median(times), 4),
        "time_s_max": round(max(times), 4),
        "time_limit_s": time_limit,
        "hard_checks_ok": all(r.hard_checks.ok for r in results),
        "overlaps": sum(len(r.hard_checks.overlaps) for r in results),
        "solver_used": best.solver_used,
        "solver_status": best.solver_status,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/layout.json"))
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument(
        "--living-room-limit",
        type=float,
        default=0.9,
        help="time limit for the living room (goal: total under 1 s)",
    )
    args = parser.parse_args()

    cases = [("living_room", json.loads(FIXTURE.read_text()), args.living_room_limit)]
    for n in (5, 10, 20, 30):
        cases.append((f"generated_{n}", generate_problem(n, seed=n), 1.0 if n <= 10 else 4.0))
    rows = []
    for name, data, limit in cases:
        for solver in ("cpsat", "greedy"):
            row = run_case(name, data, solver, limit, args.repeats)
            rows.append(row)
            print(
                f"{name:>14} {solver:>6}: {min(row['satisfied'])}-{max(row['satisfied'])}"
                f"/{row['total']} satisfied, {row['placed']}/{row['objects']} placed, "
                f"median {row['time_s_median']:.3f} s (max {row['time_s_max']:.3f}), "
                f"hard ok {row['hard_checks_ok']}, {row['solver_status']}",
                flush=True,
            )
    living = next(r for r in rows if r["case"] == "living_room" and r["solver"] == "cpsat")
    thirty = next(r for r in rows if r["case"] == "generated_30" and r["solver"] == "cpsat")
    goals = {
        "living_room_at_least_34_of_36": min(living["satisfied"]) >= 34,
        "living_room_under_1s": living["time_s_max"] < 1.0,
        "living_room_no_overlaps": living["overlaps"] == 0,
        "thirty_objects_under_5s": thirty["time_s_max"] < 5.0,
        "thirty_objects_no_overlaps": thirty["overlaps"] == 0,
    }
    report = {
        "benchmark": "layout",
        "machine": {"platform": platform.platform(), "python": sys.version.split()[0]},
        "holodeck_dfs_reference": {"living_room_satisfied": 34, "total": 36},
        "cases": rows,
        "goals": goals,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(report, indent=2) + "\n")
    print(json.dumps(goals, indent=2))
    return 0 if all(goals.values()) else 1


if __name__ == "__main__":
    raise SystemExit(main())
