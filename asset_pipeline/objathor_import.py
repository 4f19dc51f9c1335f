"""Import the assets of an objathor directory into a library, one asset per uid (id = uid).

:mod:`asset_pipeline.objathor` reads the directory (layout, frames, safety); this module builds
each asset: the mesh dict's points go to the asset frame (``M Ry(yRotOffset)``, triangles
re-wound), then the steps of :mod:`asset_pipeline.importer`: normalisation (origin at the
footprint centre of the bottom, size checks; no rescale, the dict is at real size), repair,
colliders, support surfaces, metadata and mass. Results are cached and committed one asset at a
time like ``holomj assets import`` (:mod:`asset_pipeline.manage`): the cache key hashes the
pipeline's code, the options, the uid, its annotation and the files of its folder, so a rerun of
unchanged assets is instant and a killed run resumes.

Colliders: ``shipped`` uses the dict's convex pieces (capped, pulled inside the visual mesh and
sliver-checked by :func:`asset_pipeline.hulls.postprocess`); an asset without shipped colliders
(an OBJ/GLB source, or a dict without ``colliders``) **falls back to CoACD** with a warning in
``derivation.json`` (see ``holomj assets show UID``). ``coacd`` always runs the pipeline's
CoACD with its timeout, fallback chain and cache rules (:mod:`asset_pipeline.decompose`,
:mod:`asset_pipeline.manage`).

Metadata: the category is the holomj category named in the annotation's ``category`` (else its
``synset``), by the words and aliases of ``data/categories.json`` ("eames chair" -> chair),
else the annotation's category itself in snake case; the placement comes from the ``on*``
flags (else the category's default); the mass is the annotation's (else the material estimate
of :mod:`asset_pipeline.physical`); an asset the annotation (else the dict's
``receptacleCandidate``) says is **not** a receptacle gets no support surfaces, as in
Holodeck/THOR where small objects only go on receptacles. The original annotation values,
THOR's bounding box and any size disagreement with it are recorded in ``derivation.json``.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from asset_pipeline import annotate, physical
from asset_pipeline.decompose import CoacdParams
from asset_pipeline.hulls import postprocess
from asset_pipeline.import_cache import CACHE_DIR, options_json, pipeline_version
from asset_pipeline.import_records import (
    ID_FIX,
    ImportedAsset,
    StepTimer,
    check_asset_id,
    derived_meta,
    file_sizes,
    mesh_geometry,
    source_digest,
    surface_summary,
)
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.manage import ImportSummary, JobOutcome, finish_bundle, import_cached, run_jobs
from asset_pipeline.objathor import (
    ObjathorAnnotation,
    ObjathorJob,
    ObjathorMesh,
    gltf_to_asset,
    parse_annotation,
    read_mesh,
    unity_to_asset,
)
from asset_pipeline.proximity import MeshProximity
from asset_pipeline.surfaces import support_surfaces
from holomj.errors import FormatError
from holomj.spec.assets import AssetMeta

if TYPE_CHECKING:
    from asset_pipeline.normalise import Normalisation
    from asset_pipeline.physical import MassResult, PhysicalDefaults
    from asset_pipeline.repair import Repaired

__all__ = [
    "COLLIDER_MODES",
    "ObjathorOptions",
    "cache_key",
    "import_objathor_asset",
    "process_objathor_job",
    "run_objathor_imports",
]

COLLIDER_MODES = ("shipped", "coacd")


# -- one asset -------------------------------------------------------------------------------
@dataclass(frozen=True)
class ObjathorOptions:
    """How to import: collider source, CoACD settings (for ``coacd`` and the fallback)."""

    colliders: Literal["shipped", "coacd"] = "shipped"
    coacd: CoacdParams = field(default_factory=CoacdParams)
    max_faces: int = 2_000_000


def import_objathor_asset(
    uid: str,
    mesh: ObjathorMesh,
    annotation: ObjathorAnnotation,
    options: ObjathorOptions | None = None,
) -> ImportedAsset:
    """Build the asset bundle of one objathor asset (nothing is written to disk).

    Returns an :class:`~asset_pipeline.import_records.ImportedAsset` whose report says what
    was done.
    """
    options = options or ObjathorOptions()
    where = str(mesh.source)
    check_asset_id(uid, where, fix="uids become asset ids: " + ID_FIX.removeprefix("use "))
    timer = StepTimer()
    warnings = list(annotation.warnings) + list(mesh.warnings)
    turned = _turned(mesh, annotation, warnings)
    timer.lap("normalise_repair")
    hulls = _hulls(turned, mesh, options, warnings)
    timer.lap("decompose")
    repaired = turned.repaired
    proximity = MeshProximity(repaired.physics)
    hullset = postprocess(hulls.hulls, repaired.physics, proximity, repaired.watertight)
    timer.lap("hulls")
    receptacle, receptacle_source = _receptacle(annotation, mesh)
    surfaces = [] if receptacle is False else support_surfaces(repaired.physics)
    timer.lap("surfaces")

    files: dict[str, bytes] = {}
    geometry = mesh_geometry(repaired.visuals, hullset, surfaces, files)
    category, category_source = _category(annotation)
    info = physical.category_info(category, turned.frame.size)
    massed = physical.resolve_mass(info, repaired.physics, hullset.volume, given=annotation.mass_kg)
    warnings += massed.warnings
    size_check = _size_check(turned.frame.size, annotation)
    if size_check.get("warning"):
        warnings.append(f"{uid}: {size_check['warning']}")
    derived = derived_meta(
        asset_id=uid,
        category=category,
        description=annotation.description or annotate.describe(category),
        size=turned.frame.size,
        mass_kg=massed.mass_kg,
        density_kg_m3=massed.mass_kg / hullset.volume,
        info=info,
        placement=annotation.placement or info.placement,
        geometry=geometry,
        source=f"objathor {uid} ({mesh.source.name}, {mesh.format}, front +z -> +x, "
        f"yRotOffset {mesh.y_rot_offset_deg:g} deg)",
    )
    derived |= {"license": annotation.license, "attribution": annotation.attribution}
    meta, _ = annotate.build_meta(derived, {}, {}, where)
    timer.lap("annotate")
    report = {
        "asset_id": uid,
        "source": _source_report(uid, mesh),
        "objathor": {
            "annotation": annotation.as_report(),
            "y_rot_offset_deg": mesh.y_rot_offset_deg,
            "receptacle": receptacle,
            "receptacle_source": receptacle_source,
            "category_source": category_source,
            "size_check": size_check,
        },
        "normalisation": turned.frame.as_report()
        | {"matrix": turned.matrix.round(9).tolist(), "scale": turned.scale},
        "repairs": repaired.stats,
        "watertight": repaired.watertight,
        "winding_consistent": repaired.winding_consistent,
        "degraded": hulls.degraded_reason is not None,
        "degraded_reason": hulls.degraded_reason,
        "decomposition": hulls.as_report(options.colliders),
        "quality": hullset.quality,
        "surfaces": surface_summary(surfaces),
        "physical": _physical_report(meta, info, massed, annotation, category_source),
        "files": file_sizes(files),
        "timings_s": timer.timings,
        "warnings": warnings,
    }
    return ImportedAsset(bundle=AssetBundle(meta=meta, files=files), report=report)


def _receptacle(
    annotation: ObjathorAnnotation, mesh: ObjathorMesh
) -> tuple[bool | None, str | None]:
    """Whether the asset holds things on it, and who says so: the annotation, else the mesh
    file's ``receptacleCandidate``, else nobody (None: its surfaces are kept)."""
    if annotation.receptacle is not None:
        return annotation.receptacle, "annotation"
    if mesh.receptacle_candidate is not None:
        return mesh.receptacle_candidate, "receptacleCandidate"
    return None, None


def _source_report(uid: str, mesh: ObjathorMesh) -> dict[str, Any]:
    """The report's section on the files read."""
    return {
        "file": str(mesh.source),
        "sha256": source_digest(mesh.source),
        "format": f"objathor-{mesh.format}",
        "uid": uid,
        "texture": str(mesh.texture) if mesh.texture else None,
        "vertices": sum(len(p.vertices) for p in mesh.parts),
        "faces": sum(len(p.faces) for p in mesh.parts),
        "shipped_colliders": len(mesh.colliders) if mesh.colliders else 0,
    }


def _physical_report(
    meta: AssetMeta,
    info: PhysicalDefaults,
    massed: MassResult,
    annotation: ObjathorAnnotation,
    category_source: str,
) -> dict[str, Any]:
    """The report's section on the category, the mass and how it was found."""
    return {
        "category": meta.category,
        "category_source": category_source,
        "category_known": info.known,
        "mass_kg": meta.mass,
        "mass_source": "annotation" if annotation.mass_kg is not None else massed.source,
        "mass_range_kg": list(info.mass_range_kg),
        "mass_derivation": massed.derivation,
        "friction": meta.friction,
        "placement": meta.placement,
    }


@dataclass(frozen=True)
class _Turned:
    """An objathor mesh in the asset frame, repaired: the transform from its own frame
    (``matrix`` and ``scale``), then the normalisation."""

    matrix: np.ndarray
    scale: float
    frame: Normalisation
    repaired: Repaired


def _turned(mesh: ObjathorMesh, annotation: ObjathorAnnotation, warnings: list[str]) -> _Turned:
    """``mesh`` turned from its frame (Unity's or glTF's) into the asset frame (a mirroring
    transform re-winds the faces), normalised and repaired."""
    from asset_pipeline.normalise import normalise
    from asset_pipeline.repair import repair

    where = str(mesh.source)
    if mesh.frame == "gltf":
        matrix, scale = gltf_to_asset(mesh.parts, annotation)
        if annotation.scale_m is None:
            warnings.append(f"{where}: no annotation scale; the glTF is used at its own units")
    else:
        matrix, scale = unity_to_asset(mesh.y_rot_offset_deg), 1.0
    mirrored = np.linalg.det(matrix) < 0
    turned = [
        dataclasses.replace(
            p,
            vertices=(p.vertices @ matrix.T) * scale,
            faces=p.faces[:, ::-1].copy() if mirrored else p.faces,
        )
        for p in mesh.parts
    ]
    parts, frame = normalise(turned, where, "z", "+x", None)
    repaired = repair(parts)
    if len(repaired.physics.faces) == 0:
        raise FormatError("the mesh has only degenerate faces", where=where)
    return _Turned(matrix, scale, frame, repaired)


@dataclass(frozen=True)
class _Hulls:
    """The raw collision hulls of an asset and how they were made."""

    hulls: list[np.ndarray]
    method: str
    degraded_reason: str | None
    attempts: list[dict[str, Any]]
    preprocess: str

    def as_report(self, colliders_option: str) -> dict[str, Any]:
        """The report's section on how the hulls were made."""
        return {
            "method": self.method,
            "colliders_option": colliders_option,
            "preprocess_mode": self.preprocess,
            "attempts": self.attempts,
        }


def _hulls(
    turned: _Turned, mesh: ObjathorMesh, options: ObjathorOptions, warnings: list[str]
) -> _Hulls:
    """The asset's shipped colliders (in the asset frame) when asked and there, else CoACD's
    decomposition of the repaired mesh."""
    from asset_pipeline.decompose import decompose

    where = str(mesh.source)
    if options.colliders == "shipped":
        if mesh.colliders:
            matrix, scale = turned.matrix, turned.scale
            translation = turned.frame.translation
            shipped = [(c @ matrix.T) * scale + translation for c in mesh.colliders]
            return _Hulls(shipped, "shipped", None, [], "none")
        warnings.append(f"{where}: no shipped colliders; decomposed with CoACD instead")
    repaired = turned.repaired
    manifold = repaired.watertight and repaired.winding_consistent
    decomposition = decompose(repaired.physics, options.coacd, manifold)
    if decomposition.degraded_reason:
        warnings.append(f"degraded decomposition: {decomposition.degraded_reason}")
    return _Hulls(
        decomposition.hulls,
        decomposition.method,
        decomposition.degraded_reason,
        decomposition.attempts,
        decomposition.preprocess_mode,
    )


def _category(annotation: ObjathorAnnotation) -> tuple[str, str]:
    """(holomj category, where it came from): a table category named in the annotation's
    category or synset, else the annotation's category in snake case, else the default."""
    texts = [("category", annotation.category)]
    if annotation.synset:
        texts.append(("synset", annotation.synset.split(".")[0]))
    for source, text in texts:
        if text:
            guessed = physical.guess_category(Path(re.sub(r"[/\\]", " ", text)))
            if guessed:
                return guessed, f"annotation {source} {text!r}"
    if annotation.category:
        snake = re.sub(r"[^a-z0-9]+", "_", annotation.category.lower()).strip("_")[:64]
        if snake:
            return snake, "annotation category"
    return physical.DEFAULT_CATEGORY, "default"


def _size_check(size: tuple[float, float, float], annotation: ObjathorAnnotation) -> dict:
    """Our size against THOR's bounding box (the size Holodeck placed), when known."""
    if annotation.bbox_unity_m is None:
        return {"thor_bbox_m": None}
    bx, by, bz = annotation.bbox_unity_m
    expected = (bz, bx, by)  # asset X = Unity z, Y = Unity x, Z = Unity y
    worst = max(abs(a - e) for a, e in zip(size, expected, strict=True))
    check: dict[str, Any] = {
        "thor_bbox_m": list(annotation.bbox_unity_m),
        "expected_size_m": [round(v, 6) for v in expected],
        "largest_difference_m": round(worst, 6),
    }
    if worst > max(0.02, 0.05 * max(expected)):
        check["warning"] = (
            f"size {_fmt(size)} m differs from THOR's box {_fmt(expected)} m by "
            f"{worst:.3f} m; Holodeck footprints assume THOR's"
        )
    return check


def _fmt(values: Sequence[float]) -> str:
    return " x ".join(f"{v:.3f}" for v in values)


def cache_key(job: ObjathorJob, options: ObjathorOptions) -> str:
    """Content address of one import: pipeline code, options, uid, annotation, asset files."""
    digest = hashlib.sha256()
    digest.update(pipeline_version().encode())
    digest.update(b"objathor")
    digest.update(options_json(options).encode())
    digest.update(job.uid.encode())
    digest.update(json.dumps(job.annotation, sort_keys=True, default=str).encode())
    for path in sorted(job.folder.iterdir()):
        if path.is_file() and not path.name.startswith("."):
            digest.update(path.name.encode())
            digest.update(hashlib.sha256(path.read_bytes()).digest())
    return digest.hexdigest()[:32]


def process_objathor_job(
    job: ObjathorJob,
    options: ObjathorOptions,
    cache_root: Path,
    thumbnails: bool,
    accept_fallback: bool = False,
) -> JobOutcome:
    """Import one uid into the cache (or find it there); never raises for bad input."""
    path, uid = _job_key(job)
    return import_cached(
        JobOutcome(path=path, asset_id=uid, ok=False, id_note=job.id_note),
        cache_root,
        lambda: cache_key(job, options),
        lambda key: _import_bundle(job, options, key, thumbnails, accept_fallback),
        accept_fallback,
    )


def _import_bundle(
    job: ObjathorJob, options: ObjathorOptions, key: str, thumbnails: bool, accept_fallback: bool
) -> tuple[AssetBundle, dict]:
    """Read and import ``job``: the bundle (thumbnails, ``derivation.json``) and the report."""
    if job.mesh_file is None:
        raise FormatError("no mesh file", where=str(job.folder))
    where = job.annotation_source or str(job.folder)
    if job.annotation is None:
        annotation = ObjathorAnnotation(warnings=(f"{job.uid}: no annotation; defaults used",))
    elif isinstance(job.annotation, dict) and "__error__" in job.annotation:
        raise FormatError(str(job.annotation["__error__"]))
    else:
        annotation = parse_annotation(job.annotation, f"{where}: {job.uid}")
        if annotation.uid is not None and annotation.uid != job.uid:
            note = f"{where}: the annotation's uid {annotation.uid!r} is not its key {job.uid!r}"
            annotation = dataclasses.replace(annotation, warnings=(*annotation.warnings, note))
    mesh = read_mesh(job.mesh_file, options.max_faces)
    imported = import_objathor_asset(job.uid, mesh, annotation, options)
    return finish_bundle(imported, key, thumbnails, accept_fallback)


def run_objathor_imports(
    jobs: Sequence[ObjathorJob],
    library_root: Path,
    options: ObjathorOptions,
    *,
    workers: int = 1,
    thumbnails: bool = True,
    accept_fallback: bool = False,
    on_done: Callable[[JobOutcome], None] | None = None,
) -> ImportSummary:
    """Import ``jobs`` into the library at ``library_root`` with ``workers`` processes.

    Each success is committed to the library as soon as it is done (one index rename per
    asset, so a killed run keeps what it finished and a rerun takes it from the cache); a uid
    that fails is reported and the others go on.
    """
    root = Path(library_root)
    (root / CACHE_DIR).mkdir(parents=True, exist_ok=True)
    args = (options, root / CACHE_DIR, thumbnails, accept_fallback)
    summary = run_jobs(
        jobs, process_objathor_job, args, root, workers=workers, on_done=on_done, key=_job_key
    )
    summary.outcomes.sort(key=lambda o: o.asset_id)
    return summary


def _job_key(job: ObjathorJob) -> tuple[str, str]:
    return str(job.mesh_file or job.folder), job.uid
