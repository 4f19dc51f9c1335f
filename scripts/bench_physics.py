"""Benchmark physics: validate time and real-time factor for 50, 200 and 800 objects, and
spawn-and-drop throughput and success rate. Writes JSON::

    python scripts/bench_physics.py --out bench_results/physics.json [--sizes 50 200 800] [--sleep]
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import tempfile
import time
from pathlib import Path

import mujoco
from bench_scenes import grid_house  # sibling module in scripts/
from spawn_bench import bench_populate  # sibling module in scripts/

from asset_pipeline.default_library import ensure_default_library
from holomj.jobs.folder import load_for_physics, write_scene_folder
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.physics.settle import validate_loaded


def bench_validate(library: AssetLibrary, n: int, sleep: bool, tmp: Path) -> dict:
    """Compile a grid house of ``n`` objects, then validate it with free furniture."""
    out = write_scene_folder(compile_scene(grid_house(library, n), library), tmp / f"house_{n}")
    start = time.perf_counter()
    loaded = load_for_physics(out, furniture="free")
    load_s = time.perf_counter() - start
    report = validate_loaded(loaded, sleep=sleep)
    stable = sum(1 for o in report.objects if o.stable)
    return {
        "objects": n,
        "bodies": loaded.model.nbody,
        "geoms": loaded.model.ngeom,
        "load_compile_s": round(load_s, 3),
        "validate_wall_s": round(report.wall_time_s, 3),
        "sim_time_s": round(report.sim_time_s, 3),
        "realtime_factor": round(report.realtime_factor, 3),
        "ok": report.ok,
        "stable_fraction": round(stable / max(1, len(report.objects)), 4),
        "max_penetration_m": report.max_penetration_m,
        "warnings": report.warnings,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/physics.json"))
    parser.add_argument("--sizes", type=int, nargs="*", default=[50, 200, 800])
    parser.add_argument("--spawn", type=int, nargs="*", default=[10, 30])
    parser.add_argument("--sleep", action="store_true", help="validate with MuJoCo sleep on")
    args = parser.parse_args()

    library = AssetLibrary.open(ensure_default_library())
    validate_rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.sizes:
            row = bench_validate(library, n, args.sleep, Path(tmp))
            validate_rows.append(row)
            print(json.dumps(row), flush=True)
    spawn_rows = []
    for n in args.spawn:
        row = bench_populate(n, seed=0, library=library)
        spawn_rows.append(row)
        print(json.dumps(row), flush=True)
    result = {
        "benchmark": "physics",
        "sleep": args.sleep,
        "validate": validate_rows,
        "spawn": spawn_rows,
        "mujoco": mujoco.__version__,
        "python": platform.python_version(),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
