"""Benchmark: a generated kitchen with and without articulated furniture.

Generates the issue's kitchen ("a kitchen with base cabinets, wall cabinets, a fridge, an oven
and a dishwasher") for each seed three times: with the default library (``articulated``:
counters, cabinets and appliances with doors, drawers and racks on joints, things put inside),
the same without things inside (``articulated_empty``, ``GenerateOptions(inside=False)``: the
joints' own cost) and with its rigid variant (``rigid``: ``ensure_default_library(
articulated=False)``, synthesis on demand rigid too). Per scene: objects, articulated objects
and parts (``objects.json``), the model's joints by type (the parts' hinges and slides, the
doors of the house, the free joints of what moves), degrees of freedom and geoms; then the
median over ``--repeats`` of the in-memory compile (``compile_scene`` of ``scene.json``) and of
``holomj validate OUT`` (load, settle, monitor, judge). Writes JSON::

    python scripts/bench_articulation.py --out bench_results/articulation.json [--seeds 0 1]
"""

from __future__ import annotations

import argparse
import contextlib
import json
import platform
import statistics
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path

import mujoco

PROMPT = "a kitchen with base cabinets, wall cabinets, a fridge, an oven and a dishwasher"
VARIANTS = (  # name, articulated library, things put inside
    ("articulated", True, True),
    ("articulated_empty", True, False),
    ("rigid", False, False),
)
JOINT_TYPES = {
    int(mujoco.mjtJoint.mjJNT_FREE): "free",
    int(mujoco.mjtJoint.mjJNT_BALL): "ball",
    int(mujoco.mjtJoint.mjJNT_SLIDE): "slide",
    int(mujoco.mjtJoint.mjJNT_HINGE): "hinge",
}


@contextlib.contextmanager
def switch(articulated: bool) -> Iterator[None]:
    """Synthesis on demand follows the library variant being measured."""
    from asset_pipeline import default_library

    before = default_library.ARTICULATED_BY_DEFAULT
    default_library.ARTICULATED_BY_DEFAULT = articulated
    try:
        yield
    finally:
        default_library.ARTICULATED_BY_DEFAULT = before


def _median_seconds(action, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return round(statistics.median(times), 4)


def bench_scene(folder: Path, library_root: Path, repeats: int) -> dict:
    """The row of one generated scene folder."""
    from holomj.jobs.validate import validate
    from holomj.library.store import AssetLibrary
    from holomj.mjcf.compiler import compile_scene
    from holomj.spec.base import read_json, validate_model
    from holomj.spec.scene import SceneSpec

    scene = validate_model(SceneSpec, read_json(folder / "scene.json"), "scene.json")
    library = AssetLibrary.open(library_root)
    model = compile_scene(scene, library).model
    joints: dict[str, int] = {}
    for j in range(model.njnt):
        name = JOINT_TYPES[int(model.jnt_type[j])]
        joints[name] = joints.get(name, 0) + 1
    listed = json.loads((folder / "objects.json").read_text())["objects"]
    parts = [j for o in listed for j in (o.get("joints") or []) if j.get("part")]
    report = validate(folder)
    compile_s = _median_seconds(lambda: compile_scene(scene, library), repeats)
    validate_s = _median_seconds(lambda: validate(folder), repeats)
    return {
        "objects": len(scene.objects),
        "articulated_objects": len({p["name"].split("/")[0] for p in parts}),
        "articulated_parts": len(parts),
        "part_kinds": {
            k: sum(p["kind"] == k for p in parts) for k in sorted({p["kind"] for p in parts})
        },
        "joints": dict(sorted(joints.items())),
        "njnt": int(model.njnt),
        "nv": int(model.nv),
        "nbody": int(model.nbody),
        "ngeom": int(model.ngeom),
        "compile_s": compile_s,
        "validate_s": validate_s,
        "validate_ok": report.ok,
        "stable": f"{report.counts['stable']}/{report.counts['objects']}",
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/articulation.json"))
    parser.add_argument("--seeds", type=int, nargs="+", default=[0, 1])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    from asset_pipeline.default_library import ensure_default_library
    from holomj.jobs.generate import GenerateOptions, generate_scene

    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for variant, articulated, inside in VARIANTS:
            start = time.perf_counter()
            kind = "articulated" if articulated else "rigid"
            root = ensure_default_library(Path(tmp) / kind / "library", articulated=articulated)
            library_s = time.perf_counter() - start
            for seed in args.seeds:
                out = Path(tmp) / variant / f"kitchen-s{seed}"
                with switch(articulated):
                    start = time.perf_counter()
                    options = GenerateOptions(library=root, seed=seed, render=False, inside=inside)
                    result = generate_scene(PROMPT, out, options)
                    generate_s = time.perf_counter() - start
                    row = bench_scene(out, root, args.repeats)
                row = {
                    "variant": variant,
                    "seed": seed,
                    "generate_s": round(generate_s, 2),
                    "library_build_s": round(library_s, 2),
                    "generate_ok": result.ok,
                    **row,
                }
                rows.append(row)
                print(
                    f"{variant} seed {seed}: {row['objects']} objects, "
                    f"{row['articulated_parts']} parts on {row['articulated_objects']} objects, "
                    f"joints {row['joints']}, compile {row['compile_s']} s, validate "
                    f"{row['validate_s']} s ({'ok' if row['validate_ok'] else 'NOT ok'})",
                    file=sys.stderr,
                )

    def mean(variant: str, key: str) -> float:
        return round(statistics.mean(r[key] for r in rows if r["variant"] == variant), 4)

    summary = {
        v: {k: mean(v, k) for k in ("compile_s", "validate_s", "njnt", "articulated_parts", "nv")}
        for v, _, _ in VARIANTS
    }
    record = {
        "benchmark": "articulation",
        "prompt": PROMPT,
        "seeds": args.seeds,
        "repeats": args.repeats,
        "scenes": rows,
        "mean": summary,
        "compile_ratio": round(
            summary["articulated"]["compile_s"] / summary["rigid"]["compile_s"], 3
        ),
        "validate_ratio": round(
            summary["articulated"]["validate_s"] / summary["rigid"]["validate_s"], 3
        ),
        "validate_ratio_empty": round(
            summary["articulated_empty"]["validate_s"] / summary["rigid"]["validate_s"], 3
        ),
        "mujoco": mujoco.__version__,
        "python": platform.python_version(),
        "machine": platform.machine(),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(record, indent=2) + "\n")
    keys = ("mean", "compile_ratio", "validate_ratio", "validate_ratio_empty")
    print(json.dumps({k: record[k] for k in keys}, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
