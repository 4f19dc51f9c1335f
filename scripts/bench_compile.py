"""Benchmark: compile + export of a house with 150 objects (goal: under 1 s here).

Asset processing is excluded: the objects come from the shipped default library. Writes JSON::

    python scripts/bench_compile.py --out bench_results/compile.json [--repeats 5]
"""

from __future__ import annotations

import argparse
import json
import platform
import resource
import statistics
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

import mujoco
from bench_scenes import grid_house  # sibling module in scripts/

from asset_pipeline.default_library import ensure_default_library
from holomj.jobs.folder import write_scene_folder
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.physics.smoke import simulate


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/compile.json"))
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--objects", type=int, default=150)
    args = parser.parse_args()

    library = AssetLibrary.open(ensure_default_library())
    scene = grid_house(library, args.objects)
    compile_times, export_times = [], []
    with tempfile.TemporaryDirectory() as tmp:
        tracemalloc.start()
        for i in range(args.repeats):
            start = time.perf_counter()
            compiled = compile_scene(scene, library)
            mid = time.perf_counter()
            write_scene_folder(compiled, Path(tmp) / f"out_{i}")
            end = time.perf_counter()
            compile_times.append(mid - start)
            export_times.append(end - mid)
        _, peak_python = tracemalloc.get_traced_memory()
        tracemalloc.stop()
    totals = [c + e for c, e in zip(compile_times, export_times)]
    smoke = simulate(compiled.model, 1.0)
    result = {
        "benchmark": "compile_export",
        "objects": len(scene.objects),
        "rooms": len(scene.rooms),
        "bodies": compiled.model.nbody,
        "geoms": compiled.model.ngeom,
        "repeats": args.repeats,
        "compile_s_median": round(statistics.median(compile_times), 4),
        "export_s_median": round(statistics.median(export_times), 4),
        "total_s_median": round(statistics.median(totals), 4),
        "total_s_max": round(max(totals), 4),
        "goal_s": 1.0,
        "meets_goal": statistics.median(totals) < 1.0,
        "peak_python_mb": round(peak_python / 2**20, 1),
        "max_rss_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1),
        "smoke_warnings": smoke.warnings,
        "mujoco": mujoco.__version__,
        "python": platform.python_version(),
        "machine": platform.machine(),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps(result, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
