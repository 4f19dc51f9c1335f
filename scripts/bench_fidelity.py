"""Benchmark: prompt fidelity of ``holomj generate`` on the hand-annotated dev set (issue 14).

Every selected prompt of ``scripts/eval/prompts_dev.jsonl`` runs through ``holomj batch`` (a
subprocess; the offline planner unless ``--planner llm``), and every folder it writes is scored
by ``scripts/eval/score.py``, which reads only the folder and the annotation (never the planner).
Writes JSON: count / attribute / relation / absent / defining accuracy, validation rate, the
share of scenes with every door clear, min and mean reachability for a 0.2 m robot, seconds per
room, a breakdown by difficulty, the most frequent misses, and every prompt's record. ::

    python scripts/bench_fidelity.py --out bench_results/fidelity.json [--limit 12]
        [--seeds 0] [--workers 2] [--ids e001 m001 ...] [--runs DIR] [--score-only]

``--limit N`` takes N prompts spread evenly through the file (so every difficulty is in);
``--ids`` picks prompts by id. The jobs file keeps one line per prompt of the dev set (the ones
not selected are comments), so job folders keep their ids and a re-run resumes: finished jobs
are skipped by ``holomj batch``. A failed job counts every spec of its prompt as missed.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
EVAL = ROOT / "scripts" / "eval"
KINDS = ("count", "attribute", "relation", "absent", "defining")


def _load_score() -> Any:
    spec = importlib.util.spec_from_file_location("fidelity_score", EVAL / "score.py")
    module = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    sys.modules["fidelity_score"] = module
    spec.loader.exec_module(module)
    return module


def select(prompts: list[dict[str, Any]], ids: list[str], limit: int | None) -> list[dict]:
    """The prompts to run: by id when given, then ``limit`` of them evenly spread."""
    chosen = prompts
    if ids:
        wanted = set(ids)
        unknown = wanted - {p["id"] for p in prompts}
        if unknown:
            raise SystemExit(f"--ids: unknown ids {', '.join(sorted(unknown))}")
        chosen = [p for p in prompts if p["id"] in wanted]
    if limit is not None and limit < len(chosen):
        step = len(chosen) / limit
        chosen = [chosen[int(i * step)] for i in range(limit)]
    return chosen


def parse_seeds(text: str) -> tuple[int, int]:
    """``0`` -> (0, 1); ``0:3`` -> (0, 3)."""
    if ":" in text:
        a, b = text.split(":", 1)
        return int(a), int(b)
    return int(text), int(text) + 1


def write_jobs(path: Path, prompts: list[dict[str, Any]], chosen: list[dict[str, Any]]) -> None:
    """One line per dev-set prompt (stable job ids); the prompts not chosen are comments."""
    ids = {p["id"] for p in chosen}
    lines = []
    for p in prompts:
        text = " ".join(p["prompt"].split())
        if text.startswith("#"):
            raise SystemExit(f"{p['id']}: a prompt must not start with '#'")
        lines.append(text if p["id"] in ids else f"# {p['id']} (not selected)")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")


def holomj_exe() -> str:
    """The holomj console script next to this Python, else the one on PATH."""
    local = Path(sys.executable).parent / "holomj"
    return str(local) if local.exists() else "holomj"


def spec_totals(spec: dict[str, Any]) -> dict[str, int]:
    """How many specs of each kind an annotation has (for a job that wrote no scene)."""
    objects = spec.get("objects", [])
    return {
        "count": len(objects) + (1 if spec.get("rooms") else 0) + len(spec.get("room_types", [])),
        "attribute": sum(len(o.get("attributes") or {}) for o in objects),
        "relation": len(spec.get("relations", [])),
        "absent": len(spec.get("absent", [])),
        "defining": len(spec.get("defining", [])),
    }


def miss_keys(record: dict[str, Any]) -> tuple[list[str], list[str], list[str]]:
    """(spec keys, names, relation kinds) of a record's misses."""
    specs, names, relations = [], [], []
    for row in record.get("counts", []):
        if not row["held"]:
            if row["kind"] == "object":
                specs.append(f"count {row['name']} {_count(row['spec']['count'])}")
                names.append(row["name"])
            else:
                what = row["spec"].get("type", "rooms") if row["kind"] == "room_type" else "rooms"
                spec = row["spec"].get("count", row["spec"])
                specs.append(f"count room {what} {_count(spec)}")
                names.append(f"room {what}")
    for row in record.get("attributes", []):
        if not row["held"]:
            specs.append(f"{row['kind']} {row['name']}={row['value']}")
            names.append(row["name"])
    for row in record.get("relations", []):
        if not row["held"]:
            rel = row["spec"]
            specs.append(f"relation {rel['subject']} {rel['relation']} {rel.get('object') or ''}")
            names.append(rel["subject"])
            relations.append(rel["relation"])
    for row in record.get("absent", []):
        if not row["held"]:
            specs.append(f"absent {row['name']}")
            names.append(row["name"])
    for row in record.get("defining", []):
        if not row["held"]:
            specs.append(f"defining {row['room_type']}: {row['reason']}")
            names.append(f"defining {row['room_type']}")
    return specs, names, relations


def _count(count: dict[str, int]) -> str:
    return f"eq {count['eq']}" if "eq" in count else f"ge {count.get('ge', 1)}"


def aggregate(records: list[dict[str, Any]]) -> dict[str, Any]:
    """Accuracy of every kind, validation, doors, reachability and time over ``records``."""
    held = dict.fromkeys(KINDS, 0)
    total = dict.fromkeys(KINDS, 0)
    for r in records:
        for k in KINDS:
            h, t = r["summary"][k]
            held[k] += h
            total[k] += t
    scored = [r for r in records if r.get("status") != "failed"]
    reach = [
        r["reachability"]["share"] for r in scored if r["reachability"].get("share") is not None
    ]
    cover = [
        r["reachability"]["coverage"]
        for r in scored
        if r["reachability"].get("coverage") is not None
    ]
    rooms = sum(len(r.get("scene_rooms", [])) for r in scored)
    seconds = sum(r.get("seconds", 0.0) for r in scored)
    out: dict[str, Any] = {
        "prompts": len(records),
        "scenes": len(scored),
        "failed": len(records) - len(scored),
    }
    for k in KINDS:
        out[f"{k}_accuracy"] = round(held[k] / total[k], 4) if total[k] else None
        out[f"{k}_specs"] = [held[k], total[k]]
    out["validation_rate"] = (
        round(sum(1 for r in scored if r["validation"]["ok"]) / len(records), 4)
        if records
        else None
    )
    out["doors_clear_rate"] = (
        round(sum(1 for r in scored if r["doors_clear"]) / len(scored), 4) if scored else None
    )
    out["reachability_min"] = round(min(reach), 4) if reach else None
    out["reachability_mean"] = round(statistics.mean(reach), 4) if reach else None
    out["coverage_mean"] = round(statistics.mean(cover), 4) if cover else None
    out["seconds_per_room"] = round(seconds / rooms, 2) if rooms else None
    out["seconds_per_scene"] = round(seconds / len(scored), 2) if scored else None
    return out


def failed_record(spec: dict[str, Any], job: dict[str, Any] | None) -> dict[str, Any]:
    """The record of a prompt whose job wrote no scene: every spec missed."""
    totals = spec_totals(spec)
    return {
        "id": spec["id"],
        "prompt": spec["prompt"],
        "difficulty": spec.get("difficulty"),
        "scene_type": spec.get("scene_type"),
        "status": "failed",
        "error": (job or {}).get("error") or "no job result",
        "seconds": (job or {}).get("seconds", 0.0),
        "summary": {k: [0, totals[k]] for k in KINDS},
        "validation": {"ok": False, "reason": "no scene"},
        "doors_clear": False,
        "reachability": {"share": None, "coverage": None},
    }


def run_batch(args: argparse.Namespace, jobs: Path) -> float:
    """Run ``holomj batch`` on the jobs file; returns its wall time."""
    a, b = parse_seeds(args.seeds)
    cmd = [
        holomj_exe(),
        "batch",
        str(jobs),
        "-o",
        str(args.runs),
        "--workers",
        str(args.workers),
        "--seeds",
        f"{a}:{b}",
        "--timeout",
        str(args.timeout),
        "--planner",
        args.planner,
    ]
    print("+", " ".join(cmd), flush=True)
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=ROOT, check=False)
    wall = time.perf_counter() - start
    if proc.returncode not in (0, 1):
        raise SystemExit(f"holomj batch exited with {proc.returncode}")
    return wall


def print_table(result: dict[str, Any]) -> None:
    """A short table: overall and per difficulty."""
    cols = [
        ("count", "count_accuracy"),
        ("attr", "attribute_accuracy"),
        ("rel", "relation_accuracy"),
        ("absent", "absent_accuracy"),
        ("defin", "defining_accuracy"),
        ("valid", "validation_rate"),
        ("doors", "doors_clear_rate"),
        ("reachmin", "reachability_min"),
        ("s/room", "seconds_per_room"),
    ]
    head = f"{'set':<8}{'n':>4}" + "".join(f"{c:>9}" for c, _ in cols)
    print(head)
    rows = [("all", result["aggregate"])] + list(result["by_difficulty"].items())
    for name, agg in rows:
        cells = []
        for _, key in cols:
            v = agg.get(key)
            cells.append(f"{'-':>9}" if v is None else f"{v:>9.2f}")
        print(f"{name:<8}{agg['prompts']:>4}" + "".join(cells))
    print("most frequent misses:")
    for key, n in result["top_misses"]:
        print(f"  {n:>3}  {key}")
    by_name = ", ".join(f"{k} {n}" for k, n in result["misses_by_name"])
    by_relation = ", ".join(f"{k} {n}" for k, n in result["misses_by_relation"])
    print(f"misses by name: {by_name}")
    print(f"misses by relation: {by_relation}")


def main() -> int:
    """Run the benchmark."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/fidelity.json"))
    parser.add_argument("--prompts", type=Path, default=EVAL / "prompts_dev.jsonl")
    parser.add_argument("--runs", type=Path, default=Path("bench_results/fidelity_runs"))
    parser.add_argument("--limit", type=int, default=None)
    parser.add_argument("--ids", nargs="*", default=[], help="Prompt ids (space or comma).")
    parser.add_argument("--seeds", default="0", help="A seed, or A:B for seeds A..B-1.")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=600.0, help="Seconds per job.")
    parser.add_argument("--planner", default="offline")
    parser.add_argument("--score-only", action="store_true", help="Score existing folders.")
    args = parser.parse_args()
    args.runs = args.runs.resolve()
    ids = [i for item in args.ids for i in item.split(",") if i]

    score = _load_score()
    prompts = score.load_specs(str(args.prompts))
    chosen = select(prompts, ids, args.limit)
    jobs = args.runs / "jobs.txt"
    write_jobs(jobs, prompts, chosen)
    load_start = os.getloadavg()
    wall = None if args.score_only else run_batch(args, jobs)

    summary_path = args.runs / "summary.jsonl"
    lines = summary_path.read_text().splitlines() if summary_path.is_file() else []
    results = [json.loads(line) for line in lines if line.strip()]
    by_prompt: dict[str, list[dict[str, Any]]] = {}
    for job in results:
        by_prompt.setdefault(" ".join(job["input"].split()), []).append(job)
    a, b = parse_seeds(args.seeds)
    vocab = score.Vocabulary.load()
    records = []
    for spec in chosen:
        jobs_of = {j.get("seed"): j for j in by_prompt.get(" ".join(spec["prompt"].split()), [])}
        for seed in range(a, b):
            job = jobs_of.get(seed)
            folder = args.runs / ((job or {}).get("output") or (job or {}).get("id") or "-")
            if job is None or job["status"] == "failed" or not (folder / "scene.json").is_file():
                record = failed_record(spec, job)
            else:
                record = score.score_folder(folder, spec, vocab)
                record["status"] = job["status"]
                record["seconds"] = job.get("seconds", 0.0)
            record["seed"] = seed
            record["job"] = (job or {}).get("id")
            records.append(record)

    spec_misses: Counter[str] = Counter()
    name_misses: Counter[str] = Counter()
    rel_misses: Counter[str] = Counter()
    for r in records:
        s, n, rel = miss_keys(r)
        spec_misses.update(s)
        name_misses.update(n)
        rel_misses.update(rel)
    by_difficulty = {
        d: aggregate([r for r in records if r.get("difficulty") == d])
        for d in ("easy", "medium", "hard")
        if any(r.get("difficulty") == d for r in records)
    }
    result = {
        "benchmark": "fidelity",
        "prompts_file": str(args.prompts),
        "selected": [p["id"] for p in chosen],
        "seeds": [a, b],
        "workers": args.workers,
        "planner": args.planner,
        "batch_wall_s": round(wall, 1) if wall is not None else None,
        "host": {
            "platform": platform.platform(),
            "cpus": os.cpu_count(),
            "load_start": [round(x, 2) for x in load_start],
            "load_end": [round(x, 2) for x in os.getloadavg()],
        },
        "targets": {
            "count_accuracy": 0.9,
            "relation_accuracy": 0.7,
            "attribute_accuracy": 0.8,
            "validation_rate": 1.0,
            "defining_accuracy": 1.0,
            "doors_clear_rate": 1.0,
            "reachability_min": 0.97,
        },
        "aggregate": aggregate(records),
        "by_difficulty": by_difficulty,
        "top_misses": spec_misses.most_common(10),
        "misses_by_name": name_misses.most_common(10),
        "misses_by_relation": rel_misses.most_common(10),
        "records": records,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=1, default=_json_default) + "\n")
    print_table(result)
    print(f"wrote {args.out}")
    return 0


def _json_default(value: Any) -> Any:
    if isinstance(value, float) and math.isnan(value):
        return None
    return str(value)


if __name__ == "__main__":
    sys.exit(main())
