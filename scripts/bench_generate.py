"""Benchmark: ``holomj generate`` wall time per stage for 1-, 3- and 5-room prompts.

Each prompt runs once per seed through the whole pipeline (offline planner, text retrieval with
the shipped MiniLM, layout, spawn-and-drop, validation, export; rendering unless --no-render)
into a temporary folder. The text model is loaded once before timing starts (its load time is
reported separately: a fresh process pays it once). Goal: under 10 s per room on this machine.
Writes JSON::

    python scripts/bench_generate.py --out bench_results/generate.json [--seeds 0,1] [--no-render]
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

PROMPTS: dict[int, str] = {
    1: "a cozy reading room with two armchairs and a large bookshelf",
    3: "a studio apartment with a kitchen and a bathroom",
    5: "a one-bedroom apartment",
}
TARGET_S_PER_ROOM = 10.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/generate.json"))
    parser.add_argument("--seeds", default="0,1", help="Comma-separated seeds.")
    parser.add_argument("--no-render", action="store_true", help="Skip the render stage.")
    args = parser.parse_args()
    seeds = [int(s) for s in args.seeds.split(",") if s.strip()]

    from asset_pipeline.default_library import ensure_default_library
    from holomj.jobs.generate import GenerateOptions, generate_scene
    from holomj.retrieval.text import text_encoder

    library = ensure_default_library()
    start = time.perf_counter()
    text_encoder()
    model_load_s = time.perf_counter() - start

    runs = []
    with tempfile.TemporaryDirectory(prefix="holomj-bench-generate-") as tmp:
        for expected_rooms, prompt in PROMPTS.items():
            for seed in seeds:
                options = GenerateOptions(library=library, seed=seed, render=not args.no_render)
                out = Path(tmp) / f"r{expected_rooms}_s{seed}"
                start = time.perf_counter()
                result = generate_scene(prompt, out, options)
                total = time.perf_counter() - start
                rooms = len(result.plan.rooms)
                if rooms != expected_rooms:
                    print(f"warning: {prompt!r} planned {rooms} rooms", file=sys.stderr)
                runs.append(
                    {
                        "prompt": prompt,
                        "seed": seed,
                        "rooms": rooms,
                        "objects": result.record["counts"],
                        "ok": result.report.ok,
                        "total_s": round(total, 3),
                        "per_room_s": round(total / rooms, 3),
                        "stages_s": result.timings,
                    }
                )
                print(
                    f"{rooms} room(s) seed {seed}: {total:6.2f} s "
                    f"({total / rooms:5.2f} s/room), ok={result.report.ok}, "
                    f"{result.record['counts']['objects']} objects",
                    file=sys.stderr,
                )
    summary = {}
    for expected_rooms in PROMPTS:
        group = [r for r in runs if r["prompt"] == PROMPTS[expected_rooms]]
        summary[str(expected_rooms)] = {
            "rooms": group[0]["rooms"],
            "median_total_s": round(statistics.median(r["total_s"] for r in group), 3),
            "median_per_room_s": round(statistics.median(r["per_room_s"] for r in group), 3),
            "all_ok": all(r["ok"] for r in group),
        }
    data = {
        "benchmark": "generate",
        "machine": {"python": platform.python_version(), "cpus": _cpus()},
        "render": not args.no_render,
        "text_model_load_s": round(model_load_s, 3),
        "target_s_per_room": TARGET_S_PER_ROOM,
        "summary": summary,
        "runs": runs,
        "meets_target": all(s["median_per_room_s"] < TARGET_S_PER_ROOM for s in summary.values()),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    print(json.dumps(summary, indent=2))
    return 0


def _cpus() -> int:
    import os

    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1


if __name__ == "__main__":
    raise SystemExit(main())
