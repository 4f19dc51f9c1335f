"""Benchmark the asset import pipeline on ../shared/assets and compare hulls with YCB's V-HACD.

For every chosen asset: import time, decomposition time (the CoACD attempts' wall and CPU
seconds, and whether CoACD ran at all: bodies that are already convex skip it), hull count, hull
volume ratio (total hull volume / the mesh's volume for watertight meshes, / its convex hull's
volume otherwise), max outward deviation, and the mass with how it was derived. For YCB items,
the volume IoU between our hulls and the V-HACD hulls shipped with the item (Monte Carlo over
the union of both). The summary has medians over all assets and over those CoACD ran on, and the
machine's load average (timings on a shared machine depend on it). Writes JSON::

    python scripts/bench_assets.py --out bench_results/assets.json [--preset fast|default|fine]
           [--ids ycb_005_tomato_soup_can bm_coffee_cup ...] [--all] [--samples 200000]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
import trimesh
from scipy.spatial import ConvexHull

from asset_pipeline.importer import ImportOptions, import_asset
from asset_pipeline.manage import PRESETS, coacd_params
from holomj.errors import HolomjError
from holomj.spec.assets import AssetMeta

SHARED = Path(__file__).resolve().parent.parent.parent / "shared" / "assets"
DEFAULT_IDS = [  # a modest subset: thin shells, scans, frames and open furniture
    "bm_shelving_unit",
    "bm_storage_shelving_01",
    "bm_loaf_tin",
    "bm_coffee_cup",
    "bm_bowl_01",
    "bm_square_table",
    "bm_medieval_bookcase",
    "ph_painted_wooden_stool",
    "ycb_003_cracker_box",
    "ycb_005_tomato_soup_can",
    "ycb_024_bowl",
    "ycb_019_pitcher_base",
    "ycb_065-a_cups",
]


def hull_equations(points_list: list[np.ndarray]) -> list[np.ndarray]:
    """Half-space equations (n, 4) of the convex hull of each point set."""
    return [ConvexHull(points).equations for points in points_list if len(points) >= 4]


def inside_any(points: np.ndarray, equations: list[np.ndarray]) -> np.ndarray:
    """Which points lie inside at least one convex hull."""
    inside = np.zeros(len(points), dtype=bool)
    homogeneous = np.column_stack([points, np.ones(len(points))])
    for eq in equations:
        inside |= np.all(homogeneous @ eq.T <= 1e-9, axis=1)
    return inside


def volume_iou(a: list[np.ndarray], b: list[np.ndarray], samples: int, seed: int = 0) -> float:
    """Monte Carlo IoU of two unions of convex hulls given by their vertices."""
    every = np.vstack(a + b)
    lo, hi = every.min(axis=0), every.max(axis=0)
    rng = np.random.default_rng(seed)
    points = rng.uniform(lo, hi, size=(samples, 3))
    in_a, in_b = inside_any(points, hull_equations(a)), inside_any(points, hull_equations(b))
    union = np.count_nonzero(in_a | in_b)
    return float(np.count_nonzero(in_a & in_b) / union) if union else 0.0


def our_hulls(meta: AssetMeta, files: dict[str, bytes]) -> list[np.ndarray]:
    """Vertices of each of our colliders in the asset frame (primitives as their corners)."""
    hulls = []
    for part in meta.collision:
        if part.kind == "mesh" and part.mesh is not None:
            mesh = trimesh.load(
                trimesh.util.wrap_as_stream(files[part.mesh]), file_type="obj", force="mesh"
            )
            hulls.append(np.asarray(mesh.vertices))
        elif part.kind == "box":
            corners = (
                np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
                * part.size
            )
            rot = trimesh.transformations.quaternion_matrix(part.quat)[:3, :3]
            hulls.append(corners @ rot.T + np.array(part.pos))
    return hulls


def vhacd_hulls(folder: Path) -> list[np.ndarray] | None:
    """V-HACD pieces shipped with a YCB item, moved into our asset frame (origin at the
    centre of the footprint at the bottom of the visual mesh; YCB files are Z-up already)."""
    vhacd = folder / "textured_vhacd.obj"
    visual = folder / "textured.obj"
    if not vhacd.is_file() or not visual.is_file():
        return None
    lo, hi = trimesh.load(visual, force="mesh").bounds
    offset = -np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
    pieces = trimesh.load(vhacd, force="mesh").split(only_watertight=False)
    return [np.asarray(piece.vertices) + offset for piece in pieces if len(piece.vertices) >= 4]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/assets.json"))
    parser.add_argument("--preset", default="default", choices=list(PRESETS))
    parser.add_argument("--ids", nargs="*", default=None)
    parser.add_argument("--all", action="store_true", help="every furniture and small object")
    parser.add_argument("--samples", type=int, default=200_000)
    args = parser.parse_args()

    manifest = json.loads((SHARED / "MANIFEST.json").read_text())
    entries = {a["id"]: a for a in manifest["assets"] if a["kind"] != "texture"}
    ids = sorted(entries) if args.all else (args.ids or DEFAULT_IDS)
    options = ImportOptions(coacd=coacd_params(args.preset))
    load_before = os.getloadavg()
    rows = []
    for asset_id in ids:
        entry = entries[asset_id]
        row = bench_one(asset_id, entry, options, args.samples)
        rows.append(row)
        print(json.dumps(row), flush=True)
    result = {
        "benchmark": "asset_import",
        "preset": args.preset,
        "coacd": options.coacd.__dict__,
        "assets": len(rows),
        **summarise(rows),
        "load_average_before": [round(x, 2) for x in load_before],
        "load_average_after": [round(x, 2) for x in os.getloadavg()],
        "cpus": os.cpu_count(),
        "python": platform.python_version(),
        "rows": rows,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps({k: v for k, v in result.items() if k != "rows"}, indent=2))
    return 0


def bench_one(asset_id: str, entry: dict, options: ImportOptions, samples: int) -> dict:
    """Import one manifest entry and measure it (a row of the result)."""
    path = SHARED / entry["main_file"]
    start = time.perf_counter()
    row: dict = {"id": asset_id, "category": entry["category"]}
    try:
        imported = import_asset(
            path, asset_id.replace("-", "_"), replace(options, category=entry["category"])
        )
    except HolomjError as err:
        row.update(ok=False, error=str(err), seconds=round(time.perf_counter() - start, 2))
        return row
    meta, report = imported.bundle.meta, imported.report
    quality = report.get("quality", {})
    decomposition = report.get("decomposition", {})
    coacd_attempts = [
        a for a in decomposition.get("attempts", []) if a["method"].startswith("coacd")
    ]
    derivation = report["physical"]["mass_derivation"]
    row.update(
        ok=True,
        seconds=round(time.perf_counter() - start, 2),
        decompose_seconds=report["timings_s"]["decompose"],
        coacd_ran=any(a["status"] != "skipped" for a in coacd_attempts),
        coacd_seconds=round(sum(a.get("seconds", 0.0) for a in coacd_attempts), 2),
        coacd_cpu_seconds=round(sum(a.get("cpu_seconds", 0.0) for a in coacd_attempts), 2),
        method=decomposition.get("method"),
        degraded=report.get("degraded", False),
        hulls=len(meta.collision),
        volume_ratio=quality.get("volume_ratio"),
        volume_reference=quality.get("volume_reference"),
        max_outward_deviation_mm=round(1000 * quality.get("max_outward_deviation_m", 0.0), 3),
        mass_kg=round(meta.mass, 3),
        mass_method=derivation["method"],
        mass_clamped=bool(derivation.get("clamped")),
        mass_estimate_kg=round(derivation.get("estimate_kg", meta.mass), 3),
        mass_range_kg=derivation["plausible_range_kg"],
        surfaces=len(meta.surfaces),
    )
    reference = vhacd_hulls(path.parent) if asset_id.startswith("ycb_") else None
    if reference:
        ours = our_hulls(meta, imported.bundle.files)
        row["vhacd_hulls"] = len(reference)
        row["iou_vs_vhacd"] = round(volume_iou(ours, reference, samples), 4)
    return row


def _median(values: list[float]) -> float | None:
    return round(statistics.median(values), 3) if values else None


def summarise(rows: list[dict]) -> dict:
    """Medians and counts over the rows (all successful ones, and those CoACD ran on)."""
    ok = [r for r in rows if r.get("ok")]
    ran = [r for r in ok if r["coacd_ran"]]
    ratios = [r["volume_ratio"] for r in ok if r["volume_ratio"] is not None]
    mesh_ratios = [r["volume_ratio"] for r in ok if r["volume_reference"] == "mesh"]
    ious = [r["iou_vs_vhacd"] for r in ok if "iou_vs_vhacd" in r]
    return {
        "succeeded": len(ok),
        "coacd_ran": len(ran),
        "degraded": sum(1 for r in ok if r["degraded"]),
        "seconds_median": _median([r["seconds"] for r in ok]),
        "seconds_max": max((r["seconds"] for r in ok), default=None),
        "decompose_seconds_median": _median([r["decompose_seconds"] for r in ok]),
        "coacd_seconds_median_where_run": _median([r["coacd_seconds"] for r in ran]),
        "coacd_seconds_max": max((r["coacd_seconds"] for r in ran), default=None),
        "coacd_cpu_seconds_median_where_run": _median([r["coacd_cpu_seconds"] for r in ran]),
        "volume_ratio_median": _median(ratios),
        "volume_ratio_median_where_run": _median(
            [r["volume_ratio"] for r in ran if r["volume_ratio"] is not None]
        ),
        "volume_ratio_median_watertight": _median(mesh_ratios),
        "hulls_median": statistics.median(r["hulls"] for r in ok) if ok else None,
        "masses_clamped": sum(1 for r in ok if r["mass_clamped"]),
        "iou_vs_vhacd_mean": round(statistics.mean(ious), 4) if ious else None,
    }


if __name__ == "__main__":
    sys.exit(main())
