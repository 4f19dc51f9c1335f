"""Benchmark: ``holomj batch`` throughput (scenes per hour) with 1 and 2 local workers.

A fixed list of small prompts (seed 0, no rendering) runs through the local engine in each mode:
``reuse`` (the default: a long-lived worker per slot keeps the text model between jobs) and
``fresh`` (``max_jobs_per_worker=1``: a new process per job, which pays the imports and the
model load every time). Wall time includes starting the workers. Each run also counts layouts
cut by the wall clock (they may differ between runs) and how many ``scene.xml`` files match the
first run byte for byte. Writes JSON::

    python scripts/bench_batch.py --out bench_results/batch.json [--modes reuse,fresh]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

PROMPTS = [
    "a small kitchen",
    "a bathroom with white tiles",
    "a yoga studio",
    "a small cafe",
    "a hotel room with a desk",
    "a conference room with a whiteboard",
]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/batch.json"))
    parser.add_argument("--workers", default="1,2", help="Comma-separated worker counts.")
    parser.add_argument("--modes", default="reuse,fresh", help="reuse, fresh or both.")
    args = parser.parse_args()
    worker_counts = [int(w) for w in args.workers.split(",") if w.strip()]
    modes = [m.strip() for m in args.modes.split(",") if m.strip()]

    from asset_pipeline.default_library import ensure_default_library
    from holomj.batch.job_list import read_jobs
    from holomj.batch.local import LocalEngine
    from holomj.batch.result import JobOptions
    from holomj.batch.run import run_batch

    library = ensure_default_library()
    options = JobOptions(library=library)
    runs = []
    first_scenes: dict[str, bytes] = {}
    load_start = os.getloadavg()
    with tempfile.TemporaryDirectory(prefix="holomj-bench-batch-") as tmp:
        jobs_file = Path(tmp) / "jobs.txt"
        jobs_file.write_text("".join(p + "\n" for p in PROMPTS))
        jobs = read_jobs(jobs_file)
        for mode in modes:
            for workers in worker_counts:
                engine = LocalEngine(workers, max_jobs_per_worker=1 if mode == "fresh" else 0)
                out = Path(tmp) / f"{mode}_{workers}"
                start = time.perf_counter()
                outcome = run_batch(jobs, out, options, engine)
                wall = time.perf_counter() - start
                written = [r for r in outcome.results if r.status != "failed"]
                scenes = {r.id: (out / r.id / "scene.xml").read_bytes() for r in written}
                if not first_scenes:
                    first_scenes = dict(scenes)
                runs.append(
                    {
                        "mode": mode,
                        "workers": workers,
                        "jobs": len(jobs),
                        "ok": outcome.totals.ok,
                        "unstable": outcome.totals.unstable,
                        "failed": outcome.totals.failed,
                        "wall_s": round(wall, 2),
                        "scenes_per_hour": round(len(written) * 3600.0 / wall, 1),
                        "job_s_mean": round(statistics.mean(r.seconds for r in outcome.results), 2),
                        "job_s_median": round(
                            statistics.median(r.seconds for r in outcome.results), 2
                        ),
                        "job_s_max": round(max(r.seconds for r in outcome.results), 2),
                        "worker_processes": engine.workers_started,
                        "layout_clock_cuts": sum(_clock_cut(out / r.id) for r in written),
                        "same_scene_xml_as_first_run": sum(
                            first_scenes.get(i) == xml for i, xml in scenes.items()
                        ),
                        "errors": [r.error for r in outcome.results if r.error],
                    }
                )
                print(json.dumps(runs[-1]), file=sys.stderr)
    result = {
        "benchmark": "batch",
        "machine": {
            "cpu_count": os.cpu_count(),
            "platform": platform.platform(),
            "python": platform.python_version(),
            "loadavg_1_5_15_at_start": [round(x, 2) for x in load_start],
            "loadavg_1_5_15_at_end": [round(x, 2) for x in os.getloadavg()],
        },
        "prompts": PROMPTS,
        "seed": 0,
        "render": False,
        "runs": runs,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps(result, indent=2))
    return 0


def _clock_cut(folder: Path) -> bool:
    """Whether a room's layout search was stopped by the wall clock."""
    layout = json.loads((folder / "generate.json").read_text())["layout"]
    return any("wall clock" in str(room.get("status", "")) for room in layout.values())


if __name__ == "__main__":
    sys.exit(main())
