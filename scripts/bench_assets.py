"""Benchmark the asset import pipeline on ../shared/assets and compare hulls with YCB's V-HACD.

For every chosen asset: import time, hull count, hull volume / mesh volume, max outward
deviation, mass. For YCB items, the volume IoU between our hulls and the V-HACD hulls shipped
with the item (Monte Carlo over the union of both). Writes JSON::

    python scripts/bench_assets.py --out bench_results/assets.json [--preset fast|default|fine]
           [--ids ycb_005_tomato_soup_can bm_coffee_cup ...] [--all] [--samples 200000]
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np
import trimesh
from scipy.spatial import ConvexHull

from asset_pipeline.importer import ImportOptions, import_asset
from asset_pipeline.manage import coacd_params
from holomj.errors import HolomjError
from holomj.spec.assets import AssetMeta

SHARED = Path(__file__).resolve().parent.parent.parent / "shared" / "assets"
DEFAULT_IDS = [
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
    parser.add_argument("--preset", default="default", choices=["fast", "default", "fine"])
    parser.add_argument("--ids", nargs="*", default=None)
    parser.add_argument("--all", action="store_true", help="every furniture and small object")
    parser.add_argument("--samples", type=int, default=200_000)
    args = parser.parse_args()

    manifest = json.loads((SHARED / "MANIFEST.json").read_text())
    entries = {a["id"]: a for a in manifest["assets"] if a["kind"] != "texture"}
    ids = sorted(entries) if args.all else (args.ids or DEFAULT_IDS)
    options = ImportOptions(coacd=coacd_params(args.preset))
    rows = []
    for asset_id in ids:
        entry = entries[asset_id]
        path = SHARED / entry["main_file"]
        start = time.perf_counter()
        row: dict = {"id": asset_id, "category": entry["category"]}
        try:
            imported = import_asset(path, asset_id.replace("-", "_"), options)
        except HolomjError as err:
            row.update(ok=False, error=str(err), seconds=round(time.perf_counter() - start, 2))
            rows.append(row)
            print(json.dumps(row), flush=True)
            continue
        meta, report = imported.bundle.meta, imported.report
        quality = report.get("quality", {})
        row.update(
            ok=True,
            seconds=round(time.perf_counter() - start, 2),
            method=report.get("decomposition", {}).get("method"),
            hulls=len(meta.collision),
            volume_ratio=quality.get("volume_ratio"),
            volume_reference=quality.get("volume_reference"),
            max_outward_deviation_mm=round(1000 * quality.get("max_outward_deviation_m", 0.0), 3),
            mass_kg=round(meta.mass, 3),
            surfaces=len(meta.surfaces),
        )
        reference = vhacd_hulls(path.parent) if asset_id.startswith("ycb_") else None
        if reference:
            ours = our_hulls(meta, imported.bundle.files)
            row["vhacd_hulls"] = len(reference)
            row["iou_vs_vhacd"] = round(volume_iou(ours, reference, args.samples), 4)
        rows.append(row)
        print(json.dumps(row), flush=True)
    ok = [r for r in rows if r.get("ok")]
    ious = [r["iou_vs_vhacd"] for r in ok if "iou_vs_vhacd" in r]
    result = {
        "benchmark": "asset_import",
        "preset": args.preset,
        "coacd": options.coacd.__dict__,
        "assets": len(rows),
        "succeeded": len(ok),
        "seconds_median": round(statistics.median(r["seconds"] for r in ok), 2) if ok else None,
        "seconds_max": max((r["seconds"] for r in ok), default=None),
        "hulls_median": statistics.median(r["hulls"] for r in ok) if ok else None,
        "iou_vs_vhacd_mean": round(statistics.mean(ious), 4) if ious else None,
        "python": platform.python_version(),
        "rows": rows,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps({k: v for k, v in result.items() if k != "rows"}, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
