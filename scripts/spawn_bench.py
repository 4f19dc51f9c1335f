"""Throughput of spawn-and-drop: objects placed per second and success rate.

``bench_populate(n, seed)`` drops ``n`` small objects (a mix of ten categories) onto a static
dining table and into a bookshelf of the default library, each in a one-room scene, and reports
both. Timings include compiling the drop model.
"""

from __future__ import annotations

import time
from typing import Any

from holomj.library.store import AssetLibrary
from holomj.physics.spawn import populate
from holomj.seeds import seed_rng
from holomj.spec.scene import Room, SceneObject, SceneSpec

BENCH_CATEGORIES = (
    "mug",
    "book",
    "bowl",
    "apple",
    "toy_block",
    "bottle",
    "cup",
    "plate",
    "candle",
    "remote",
)
RECEPTACLES = {"table": "dining_table", "bookshelf": "bookshelf"}


def bench_scene(library: AssetLibrary, category: str) -> SceneSpec:
    """A 4 x 4 m room with one static receptacle (the first asset of ``category``) at its centre."""
    asset = library.by_category(category)[0].meta.id
    return SceneSpec(
        name=f"bench_{category}",
        rooms=[Room(id="room", polygon=[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)])],
        objects=[
            SceneObject(
                id="receptacle",
                asset=asset,
                position=(2.0, 2.0, 0.0),
                yaw_deg=30.0,
                static=True,
                room="room",
            )
        ],
    )


def bench_requests(n: int) -> list[tuple[str, int]]:
    """``n`` objects, cycling through :data:`BENCH_CATEGORIES`."""
    counts = [0] * len(BENCH_CATEGORIES)
    for k in range(n):
        counts[k % len(BENCH_CATEGORIES)] += 1
    return [(c, k) for c, k in zip(BENCH_CATEGORIES, counts) if k]


def bench_populate(
    n: int,
    seed: int,
    *,
    library: AssetLibrary | None = None,
    receptacles: dict[str, str] | None = None,
    nthread: int | None = None,
) -> dict[str, Any]:
    """Place ``n`` objects on each receptacle; per receptacle: seconds, placed, success rate,
    objects placed per second, candidate attempts and the mean attempts per placed object."""
    if library is None:
        from asset_pipeline.default_library import ensure_default_library

        library = AssetLibrary.open(ensure_default_library())
    results: dict[str, Any] = {"n": n, "seed": seed}
    for label, category in (receptacles or RECEPTACLES).items():
        scene = bench_scene(library, category)
        start = time.perf_counter()
        result = populate(
            scene,
            library,
            "receptacle",
            bench_requests(n),
            seed_rng(seed),
            nthread=nthread,
        )
        seconds = time.perf_counter() - start
        placed = sum(p.accepted for p in result.placements)
        attempts = sum(p.attempts for p in result.placements)
        results[label] = {
            "receptacle": scene.objects[0].asset,
            "seconds": round(seconds, 3),
            "placed": placed,
            "requested": n,
            "success_rate": round(placed / n, 3) if n else 1.0,
            "objects_per_s": round(placed / seconds, 2) if seconds > 0 else 0.0,
            "attempts": attempts,
            "attempts_per_placed": round(attempts / placed, 2) if placed else None,
            "surfaces_used": sorted(
                {p.surface_index for p in result.placements if p.surface_index is not None}
            ),
        }
    return results
