"""Benchmark procedural synthesis: time per asset, and the whole default library build.

For every registered category and each of its default-library variants: the time to generate
and assemble the asset in memory (target: under 0.2 s per asset); then the time and size of a
full default-library build on disk (shared texture images are hard links, counted once), and
its collider audit (the largest visual-outside-collider gap, limit 5 mm). Writes JSON::

    python scripts/bench_synthesis.py --out bench_results/synthesis.json [--repeat 1]
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import tempfile
import time
from pathlib import Path

from build_default_library import disk_bytes  # sibling module in scripts/

from asset_pipeline.collider_audit import GAP_LIMIT_M
from asset_pipeline.procedural import (
    CATEGORIES,
    build_default_library,
    default_variants,
    generate_asset,
)

TARGET_PER_ASSET_S = 0.2


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/synthesis.json"))
    parser.add_argument("--repeat", type=int, default=1, help="Timed builds per asset.")
    args = parser.parse_args()
    per_asset: list[dict[str, object]] = []
    gaps: list[tuple[float, str]] = []
    for asset_id, category, size, seed in default_variants():
        best = float("inf")
        for _ in range(max(1, args.repeat)):
            start = time.perf_counter()
            bundle = generate_asset(category, asset_id, size, seed)
            best = min(best, time.perf_counter() - start)
        per_asset.append({"asset": asset_id, "category": category, "seconds": round(best, 5)})
        gaps.append((bundle.meta.collider_gap_m or 0.0, asset_id))
    times = [float(a["seconds"]) for a in per_asset]  # type: ignore[arg-type]
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        root = build_default_library(Path(tmp) / "library")
        build_s = time.perf_counter() - start
        files, size_bytes = disk_bytes(root)
    kinds: dict[str, int] = {}
    for info in CATEGORIES.values():
        kinds[info.kind] = kinds.get(info.kind, 0) + 1
    result = {
        "benchmark": "synthesis",
        "host": platform.node(),
        "categories": len(CATEGORIES),
        "categories_by_kind": kinds,
        "assets": len(per_asset),
        "per_asset_s": {
            "median": round(statistics.median(times), 5),
            "p95": round(sorted(times)[int(0.95 * (len(times) - 1))], 5),
            "max": round(max(times), 5),
            "target": TARGET_PER_ASSET_S,
            "over_target": [a["asset"] for a in per_asset if a["seconds"] > TARGET_PER_ASSET_S],  # type: ignore[operator]
        },
        "library_build_s": round(build_s, 3),
        "library_bytes": size_bytes,
        "library_files": files,
        "collider_gap_mm": {
            "worst": round(1000 * max(gaps)[0], 1),
            "worst_asset": max(gaps)[1],
            "over_limit": [a for g, a in gaps if g > GAP_LIMIT_M],
        },
        "slowest": sorted(per_asset, key=lambda a: -float(a["seconds"]))[:10],  # type: ignore[arg-type]
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps({k: v for k, v in result.items() if k != "slowest"}, indent=2))


if __name__ == "__main__":
    main()
