"""Benchmark: ``holomj vary`` on one scene folder: how many of N variants validate, and the time
per variant (median and total, draws included). Writes JSON::

    python scripts/bench_vary.py OUT -n 100 --out bench_results/vary.json [-o DIR] [--seed 0]
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
from collections import Counter
from pathlib import Path
from typing import Any

from holomj.jobs.library import resolve_library
from holomj.jobs.vary import vary_folder


def measure(folder: Path, count: int, out_dir: Path, seed: int) -> dict[str, Any]:
    """Run the vary job and summarise it (every variant's record is kept under ``variants``)."""
    result = vary_folder(
        folder, count, out_dir, seed=seed, library_path=resolve_library(None), log=print
    )
    seconds = [variant.seconds for variant in result.variants]
    return {
        "folder": str(folder),
        "count": count,
        "validated": result.validated,
        "not_validated": [v.name for v in result.variants if not v.ok],
        "draws": dict(Counter(v.tries for v in result.variants)),
        "seconds_total": result.seconds,
        "seconds_per_variant_median": round(statistics.median(seconds), 3),
        "seconds_per_variant_mean": round(statistics.fmean(seconds), 3),
        "refused_operations": sum(len(v.refused) for v in result.variants),
        "tasks_dropped": sum(len(v.tasks_dropped) for v in result.variants),
        "variants": [
            {
                "name": v.name,
                "ok": v.ok,
                "tries": v.tries,
                "seconds": v.seconds,
                "refused": v.refused,
                "tasks_kept": len(v.tasks_kept),
            }
            for v in result.variants
        ],
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="a scene folder (holomj generate)")
    parser.add_argument("-n", "--count", type=int, default=100)
    parser.add_argument("-o", "--out-dir", type=Path, help="variants here (default: a temp dir)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, help="write the JSON here (default: print it)")
    args = parser.parse_args(argv)
    out_dir = args.out_dir or Path(tempfile.mkdtemp(prefix="holomj-vary-"))
    result = measure(args.folder, args.count, out_dir, args.seed)
    text = json.dumps(result, indent=2)
    if args.out:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(text + "\n")
    summary = {key: value for key, value in result.items() if key != "variants"}
    print(json.dumps(summary, indent=2))
    return 0 if result["validated"] == args.count else 1


if __name__ == "__main__":
    raise SystemExit(main())
