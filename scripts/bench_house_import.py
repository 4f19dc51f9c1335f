"""Benchmark: real ProcTHOR houses through ``holomj compile`` (made to stand) and ``validate``.

Compiles every house in ``../shared/procthor/houses/`` and the README's example house
(``examples/procthor_house.json``) with default options (a refused house is recorded with its
one-line error), then validates each folder as ``holomj validate OUT`` does. Per house:
objects as imported and kept, substituted / scaled stand-ins, objects moved / dropped onto
receptacles / separated / moved to another receptacle / left out / unsaved, penetrations at
t = 0 before and after (count, deepest), compile seconds (and the stage's own split), and the
validation verdict.

The houses fall into two fixed halves by their place in the sorted list of file names:
``develop`` (even places) and ``check`` (odd places), so that a change tuned on one half is
judged on the other; each row names its half. Writes JSON::

    python scripts/bench_house_import.py --out bench_results/house_import.json [--library DIR]
        [--half develop|check]
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

from holomj.errors import HolomjError
from holomj.jobs.compile import compile_file
from holomj.jobs.library import resolve_library
from holomj.jobs.validate import validate

REPO = Path(__file__).resolve().parents[1]
HOUSES = REPO.parent / "shared" / "procthor" / "houses"
EXAMPLE = REPO / "examples" / "procthor_house.json"
GOAL_S = 60.0  # a real 4-room house, on a 2-core machine


def houses() -> list[Path]:
    """The shared real houses (when present) and the example house."""
    found = sorted(HOUSES.glob("*.json")) if HOUSES.is_dir() else []
    if not found:
        print(f"note: no houses in {HOUSES}; only the example house", file=sys.stderr)
    return sorted([*found, EXAMPLE], key=lambda p: p.name)


def half_of(index: int) -> str:
    """The fixed half of the house at ``index`` of the sorted list."""
    return "develop" if index % 2 == 0 else "check"


def _scaled(substitution: dict) -> bool:
    scale = substitution.get("scale", 1.0)
    values = scale if isinstance(scale, list | tuple) else [scale]
    return any(abs(float(v) - 1.0) > 1e-6 for v in values)


def bench_house(path: Path, library: Path, root: Path) -> dict:
    """Compile and validate one house; its row of the benchmark."""
    out = root / path.stem
    start = time.perf_counter()
    try:
        report = compile_file(path, out, library_path=library, check_seconds=0.0)
    except HolomjError as err:
        seconds = round(time.perf_counter() - start, 2)
        return {"house": path.name, "error": err.one_line(), "compile_s": seconds}
    compile_s = time.perf_counter() - start
    start = time.perf_counter()
    verdict = validate(out)
    validate_s = time.perf_counter() - start
    stand = report.stand.to_dict() if report.stand else {}
    before = stand.get("penetrations_before", {})
    after = stand.get("penetrations_after", {})
    return {
        "house": path.name,
        "objects": stand.get("objects_imported", report.scene.objects),
        "kept": stand.get("objects_kept", report.scene.objects),
        "kept_share": stand.get("kept_share", 1.0),
        "relocated": len(stand.get("relocated", [])),
        "left_out": len(stand.get("left_out", [])),
        "left_out_objects": stand.get("left_out", []),
        "substituted": len(report.substitutions),
        "scaled": sum(_scaled(s) for s in report.substitutions),
        "boxes": sum(s["used_asset"] == "builtin:box" for s in report.substitutions),
        "merged": len(report.merged),
        "moved": len(stand.get("moved", [])),
        "settled_only": stand.get("settled_only", {}).get("objects", 0),
        "dropped": len(stand.get("dropped", [])),
        "separated": len(stand.get("separated", [])),
        "unsaved": len(stand.get("unsaved", [])),
        "unsaved_objects": stand.get("unsaved", []),
        "penetrations_before": before.get("count"),
        "max_penetration_before_m": before.get("max_m"),
        "penetrations_after": after.get("count"),
        "max_penetration_after_m": after.get("max_m"),
        "compile_s": round(compile_s, 2),
        "stand_s": stand.get("stand_seconds", {}),
        "valid": report.valid,
        "validate_ok": verdict.ok,
        "validate_stable": f"{verdict.counts['stable']}/{verdict.counts['objects']}",
        "validate_penetrations": verdict.counts["penetrations"],
        "validate_max_penetration_m": verdict.max_penetration_m,
        "validate_s": round(validate_s, 2),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/house_import.json"))
    parser.add_argument("--library", type=Path, default=None, help="asset library (default: ours)")
    parser.add_argument("--half", choices=("develop", "check"), default=None)
    args = parser.parse_args()

    library = resolve_library(args.library)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for index, path in enumerate(houses()):
            if args.half is not None and half_of(index) != args.half:
                continue
            row = {"half": half_of(index), **bench_house(path, library, Path(tmp))}
            rows.append(row)
            if "error" in row:
                print(f"{row['house']}: REFUSED: {row['error']}", file=sys.stderr)
                continue
            print(
                f"{row['house']}: {row['kept']}/{row['objects']} objects kept "
                f"({row['left_out']} left out, {row['relocated']} to another receptacle), "
                f"{row['substituted']} substituted "
                f"({row['scaled']} scaled), {row['moved']} moved, {row['dropped']} dropped, "
                f"{row['separated']} separated, {row['unsaved']} unsaved; penetrations "
                f"{row['penetrations_before']} -> {row['penetrations_after']}; "
                f"compile {row['compile_s']} s; validate "
                f"{'ok' if row['validate_ok'] else 'NOT ok'} ({row['validate_stable']} stable)",
                file=sys.stderr,
            )
    result = {
        "benchmark": "house_import",
        "houses": rows,
        "valid": sum(bool(r.get("validate_ok")) for r in rows),
        "refused": sum("error" in r for r in rows),
        "below_97_percent": sum(r.get("kept_share", 0.0) < 0.97 for r in rows),
        "goal_compile_s": GOAL_S,
        "max_compile_s": max(r["compile_s"] for r in rows),
        "meets_goal": all(r["compile_s"] < GOAL_S for r in rows),
        "mujoco": mujoco.__version__,
        "python": platform.python_version(),
        "machine": platform.machine(),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps(result, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
