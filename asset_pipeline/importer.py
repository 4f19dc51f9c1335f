"""Import one mesh file into a simulation-ready asset bundle (nothing is written to disk).

``import_asset(path, asset_id, options)`` runs: load (flatten the scene, keep materials) ->
normalise (Z up, front +X, optional uniform scale, origin at the footprint centre of the
bottom) -> repair (weld, drop degenerate/duplicate faces, consistent winding) -> CoACD in a
child process with a fallback chain -> hull post-processing (vertex cap, pull inside the
visual, slivers to boxes) -> support surfaces -> metadata (category table, sidecar) and the
mass, from the category's material and the mesh's material volume, never from the hulls (see
:mod:`asset_pipeline.physical`; ``report["physical"]["mass_derivation"]`` says how).

The report's ``degraded`` / ``degraded_reason`` say whether CoACD's result was replaced by a
fallback (coarser settings or the single convex hull) because CoACD was unavailable, crashed
or timed out.

URDF and MJCF files (``.urdf``; ``.xml``/``.mjcf`` whose root is ``<robot>`` or
``<mujoco>``) go to :func:`asset_pipeline.articulated_import.import_articulated`: the same steps
per link, and the joints, handles and interior surfaces of an articulated asset.

The bundle holds ``visual_K.obj`` (one per material, with ``vt`` when textured),
``texture_K.png`` and ``hull_KK.obj``; no thumbnails. Its bytes are deterministic for the same
input and options. The report is JSON-able and says what was done and how well.
"""

from __future__ import annotations

import hashlib
import time
from pathlib import Path

from asset_pipeline import annotate, physical
from asset_pipeline.decompose import CoacdParams, decompose
from asset_pipeline.hulls import collision_records, postprocess
from asset_pipeline.import_records import (
    ImportedAsset,
    ImportOptions,
    check_asset_id,
    physical_record,
    visual_records,
)
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.load import load_file
from asset_pipeline.normalise import normalise
from asset_pipeline.proximity import MeshProximity
from asset_pipeline.repair import repair
from asset_pipeline.surfaces import support_surfaces
from holomj.errors import FormatError

__all__ = ["CoacdParams", "ImportOptions", "ImportedAsset", "import_asset"]


def import_asset(
    path: Path | str, asset_id: str, options: ImportOptions | None = None
) -> ImportedAsset:
    """Import ``path`` as asset ``asset_id``; raise FormatError/SpecError for bad input."""
    options = options or ImportOptions()
    path = Path(path)
    where = str(path)
    from asset_pipeline.articulated_import import articulated_format, import_articulated

    if articulated_format(path) is not None:  # URDF or MJCF: an articulated asset
        return import_articulated(path, asset_id, options)
    check_asset_id(asset_id)
    timings: dict[str, float] = {}
    clock = time.perf_counter()

    def lap(name: str) -> None:
        nonlocal clock
        now = time.perf_counter()
        timings[name] = round(now - clock, 3)
        clock = now

    sidecar_path = options.sidecar if options.sidecar is not None else find_sidecar(path)
    sidecar = annotate.read_sidecar(Path(sidecar_path)) if sidecar_path else {}
    sidecar_where = str(sidecar_path) if sidecar_path else where
    loaded = load_file(path, options.max_faces)
    lap("load")
    up_axis = options.up_axis or ("y" if loaded.format in ("glb", "gltf") else "z")
    parts, frame = normalise(loaded.parts, where, up_axis, options.front, options.size)
    repaired = repair(parts)
    if len(repaired.physics.faces) == 0:
        raise FormatError("the mesh has only degenerate faces", where=where)
    lap("normalise_repair")
    manifold = repaired.watertight and repaired.winding_consistent
    decomposition = decompose(repaired.physics, options.coacd, manifold)
    lap("decompose")
    proximity = MeshProximity(repaired.physics)
    hullset = postprocess(decomposition.hulls, repaired.physics, proximity, repaired.watertight)
    lap("hulls")
    surfaces = support_surfaces(repaired.physics)
    lap("surfaces")

    files: dict[str, bytes] = {}
    visual = visual_records(repaired.visuals, files, {})
    collision = collision_records(hullset.colliders, files)
    volume = hullset.volume

    guessed = physical.guess_category(path)
    if options.category:
        category, category_source = options.category, "option"
    elif sidecar.get("category"):
        category, category_source = str(sidecar["category"]), "sidecar"
    elif guessed:
        category, category_source = guessed, "file name"
    else:
        category, category_source = physical.DEFAULT_CATEGORY, "default"
    info = physical.category_info(category, frame.size)
    given = options.mass_kg
    if given is None:
        given = annotate.sidecar_number(sidecar, "mass_kg", sidecar_where)
    density = annotate.sidecar_number(sidecar, "density_kg_m3", sidecar_where)
    massed = physical.resolve_mass(info, repaired.physics, volume, given=given, density=density)
    mass = massed.mass_kg
    lap("mass")
    derived = {
        "id": asset_id,
        "category": category,
        "description": annotate.describe(category),
        "size": list(frame.size),
        "mass_kg": mass,
        # The density of the collision volume that gives this mass (AssetMeta's meaning).
        "density_kg_m3": density if density is not None else mass / volume,
        "friction": info.friction,
        "placement": list(info.placement),
        "upright": info.upright,
        "front": "+x",
        "visual": visual,
        "collision": collision,
        "maxhullvert": hullset.maxhullvert,
        "surfaces": [
            {"height": s.height, "polygon": [list(p) for p in s.polygon], "area_m2": s.area}
            for s in surfaces
        ],
        "source": f"{path.name} (up {up_axis}, front {options.front} -> +x, "
        f"scale {frame.scale:.6g})",
    }
    explicit = {"category": options.category, "description": options.description}
    if options.mass_kg is not None:
        explicit["mass_kg"] = float(options.mass_kg)
    meta, meta_warnings = annotate.build_meta(derived, sidecar, explicit, sidecar_where)
    lap("annotate")

    warnings = loaded.warnings + massed.warnings + meta_warnings
    if decomposition.degraded:
        warnings.append(f"degraded decomposition: {decomposition.degraded_reason}")
    report = {
        "asset_id": asset_id,
        "source": {
            "file": str(path),
            "sha256": hashlib.sha256(path.read_bytes()).hexdigest(),
            "format": loaded.format,
            "parts": len(loaded.parts),
            "vertices": loaded.vertex_count,
            "faces": loaded.face_count,
            "sidecar": str(sidecar_path) if sidecar_path else None,
        },
        "normalisation": frame.as_report() | {"requested_size_m": options.size},
        "repairs": repaired.stats,
        "watertight": repaired.watertight,
        "winding_consistent": repaired.winding_consistent,
        "degraded": decomposition.degraded,
        "degraded_reason": decomposition.degraded_reason,
        "decomposition": {
            "method": decomposition.method,
            "preprocess_mode": decomposition.preprocess_mode,
            "attempts": decomposition.attempts,
            "fallback_reason": "; ".join(
                f"{a['method']}: {a['reason']}"
                for a in decomposition.attempts
                if a["status"] not in ("ok", "skipped") and "reason" in a
            )
            or None,
        },
        "quality": hullset.quality,
        "surfaces": [{"height": s.height, "area_m2": s.area} for s in surfaces],
        "physical": physical_record(meta, info, massed, category_source),
        "files": {name: len(data) for name, data in sorted(files.items())},
        "timings_s": timings,
        "warnings": warnings,
    }
    return ImportedAsset(bundle=AssetBundle(meta=meta, files=files), report=report)


def find_sidecar(path: Path) -> Path | None:
    """The default sidecar of ``path`` (see :mod:`asset_pipeline.annotate`)."""
    return annotate.find_sidecar(path)
