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

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from asset_pipeline import annotate, physical
from asset_pipeline.articulated_import import articulated_format, import_articulated
from asset_pipeline.decompose import CoacdParams, Decomposition, decompose
from asset_pipeline.hulls import HullSet, postprocess
from asset_pipeline.import_records import (
    ImportedAsset,
    ImportOptions,
    Sidecar,
    StepTimer,
    asked_mass,
    check_asset_id,
    chosen_category,
    derived_meta,
    explicit_fields,
    file_sizes,
    mesh_geometry,
    physical_record,
    source_digest,
    surface_summary,
)
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.load import LoadedFile, load_file
from asset_pipeline.normalise import Normalisation, UpAxis, normalise
from asset_pipeline.proximity import MeshProximity
from asset_pipeline.repair import Repaired, repair
from asset_pipeline.surfaces import Surface, support_surfaces
from holomj.errors import FormatError

__all__ = ["CoacdParams", "ImportOptions", "ImportedAsset", "import_asset"]


def import_asset(
    path: Path | str, asset_id: str, options: ImportOptions | None = None
) -> ImportedAsset:
    """Import ``path`` as asset ``asset_id``; raise FormatError/SpecError for bad input."""
    options = options or ImportOptions()
    path = Path(path)
    if articulated_format(path) is not None:  # URDF or MJCF: an articulated asset
        return import_articulated(path, asset_id, options)
    check_asset_id(asset_id)
    timer = StepTimer()
    sidecar = Sidecar.of(path, options.sidecar)
    mesh = _processed(path, options, timer)
    files: dict[str, bytes] = {}
    geometry = mesh_geometry(mesh.repaired.visuals, mesh.hullset, mesh.surfaces, files)
    category, category_source = chosen_category(path, options.category, sidecar)
    info = physical.category_info(category, mesh.frame.size)
    given, density = asked_mass(options.mass_kg, sidecar)
    volume = mesh.hullset.volume
    massed = physical.resolve_mass(
        info, mesh.repaired.physics, volume, given=given, density=density
    )
    timer.lap("mass")
    derived = derived_meta(
        asset_id=asset_id,
        category=category,
        description=annotate.describe(category),
        size=mesh.frame.size,
        mass_kg=massed.mass_kg,
        density_kg_m3=density if density is not None else massed.mass_kg / volume,
        info=info,
        placement=info.placement,
        geometry=geometry,
        source=f"{path.name} (up {mesh.up_axis}, front {options.front} -> +x, "
        f"scale {mesh.frame.scale:.6g})",
    )
    explicit = explicit_fields(options.category, options.description, options.mass_kg)
    meta, meta_warnings = annotate.build_meta(derived, sidecar.data, explicit, sidecar.where)
    timer.lap("annotate")
    warnings = mesh.loaded.warnings + massed.warnings + meta_warnings
    if mesh.decomposition.degraded:
        warnings.append(f"degraded decomposition: {mesh.decomposition.degraded_reason}")
    report = {
        "asset_id": asset_id,
        **_report(path, sidecar, mesh, options),
        "physical": physical_record(meta, info, massed, category_source),
        "files": file_sizes(files),
        "timings_s": timer.timings,
        "warnings": warnings,
    }
    return ImportedAsset(bundle=AssetBundle(meta=meta, files=files), report=report)


@dataclass(frozen=True)
class _ProcessedMesh:
    """A mesh file after the geometry steps: loaded, normalised, repaired, decomposed into
    hulls, with its support surfaces."""

    loaded: LoadedFile
    up_axis: UpAxis
    frame: Normalisation
    repaired: Repaired
    decomposition: Decomposition
    hullset: HullSet
    surfaces: list[Surface]


def _processed(path: Path, options: ImportOptions, timer: StepTimer) -> _ProcessedMesh:
    """The geometry steps of an import (load, normalise, repair, decompose, hulls, surfaces),
    each timed."""
    loaded = load_file(path, options.max_faces)
    timer.lap("load")
    up_axis = options.up_axis or ("y" if loaded.format in ("glb", "gltf") else "z")
    parts, frame = normalise(loaded.parts, str(path), up_axis, options.front, options.size)
    repaired = repair(parts)
    if len(repaired.physics.faces) == 0:
        raise FormatError("the mesh has only degenerate faces", where=str(path))
    timer.lap("normalise_repair")
    manifold = repaired.watertight and repaired.winding_consistent
    decomposition = decompose(repaired.physics, options.coacd, manifold)
    timer.lap("decompose")
    proximity = MeshProximity(repaired.physics)
    hullset = postprocess(decomposition.hulls, repaired.physics, proximity, repaired.watertight)
    timer.lap("hulls")
    surfaces = support_surfaces(repaired.physics)
    timer.lap("surfaces")
    return _ProcessedMesh(loaded, up_axis, frame, repaired, decomposition, hullset, surfaces)


def _report(
    path: Path, sidecar: Sidecar, mesh: _ProcessedMesh, options: ImportOptions
) -> dict[str, Any]:
    """The report's sections on the source file and the geometry steps."""
    decomposition = mesh.decomposition
    return {
        "source": {
            "file": str(path),
            "sha256": source_digest(path),
            "format": mesh.loaded.format,
            "parts": len(mesh.loaded.parts),
            "vertices": mesh.loaded.vertex_count,
            "faces": mesh.loaded.face_count,
            "sidecar": str(sidecar.path) if sidecar.path else None,
        },
        "normalisation": mesh.frame.as_report() | {"requested_size_m": options.size},
        "repairs": mesh.repaired.stats,
        "watertight": mesh.repaired.watertight,
        "winding_consistent": mesh.repaired.winding_consistent,
        "degraded": decomposition.degraded,
        "degraded_reason": decomposition.degraded_reason,
        "decomposition": _decomposition_report(decomposition),
        "quality": mesh.hullset.quality,
        "surfaces": surface_summary(mesh.surfaces),
    }


def _decomposition_report(decomposition: Decomposition) -> dict[str, Any]:
    """How the collision hulls were made: the method, CoACD's preprocessing, every attempt and,
    when a fallback was taken, why."""
    return {
        "method": decomposition.method,
        "preprocess_mode": decomposition.preprocess_mode,
        "attempts": decomposition.attempts,
        "fallback_reason": "; ".join(
            f"{a['method']}: {a['reason']}"
            for a in decomposition.attempts
            if a["status"] not in ("ok", "skipped") and "reason" in a
        )
        or None,
    }
