"""Import an articulated file (URDF or MJCF) as one articulated asset (nothing is written).

``import_articulated(path, asset_id, options)`` reads the file's kinematic tree
(:mod:`asset_pipeline.urdf`, :mod:`asset_pipeline.mjcf_import`) and:

1. **bodies**: the root link(s) and everything fixed to them are the *carcass*; every moving
   joint (hinge or slide) starts a *part*: its child link and everything fixed to it. A part
   under another part hangs on it (``parent``). A moving link without geometry (PartNet-
   Mobility's ``link_N_helper`` of a screw joint) takes its child links' geometry, which then
   moves on its joint only (the child's joint is dropped, with a warning); one without any is
   dropped.
2. **closed pose**: a joint's *closed* value is the pose the file gives (URDF: 0, MJCF:
   ``qpos0``) clamped into its range. The part's geometry (and its sub-parts) is moved there;
   the opening direction is the one with more travel (the axis is flipped when that is the
   negative one), so positive values open and 0 is closed, as in holomj's own assets. An
   unlimited (continuous) hinge gets the range (-pi, pi).
3. **frame**: Z up (``--up`` converts a Y-up file), metres (``--size`` scales uniformly: needed
   for PartNet-Mobility, whose models are normalised), origin at the centre of the footprint at
   the bottom of the closed asset. The front is ``--front`` unless that is the default ``+x``:
   then it is the side the parts open towards (the mean horizontal direction in which the
   parts' centres move as they open), so PartNet-Mobility models (front -X) turn to face +X.
4. **per body** as for any import: repair, CoACD (each body on its own, with the preset's
   settings, timeout and fallbacks), hull post-processing, visual meshes (``visual_K.obj`` for
   the carcass, ``<part>_visual_K.obj`` and ``<part>_hull_KK.obj`` for parts).
5. **mass**: the whole asset's mass as for a mesh import (category material x material volume
   of all bodies, clamped to the category's range; ``--mass`` or a sidecar wins), shared among
   the bodies by their material volume, the moving parts at most 80 %.
6. **joints**: the file's damping, friction loss and armature where it gives them (> 0), else
   holomj's defaults for furniture (a hinge damped by 20 N m s/rad per metre of handle lever,
   0.6 N m friction; a slide 60 N s/m, 3 N); a hinge whose axis is not vertical (a lid, a
   drop-down door) gets the counterbalance spring of the procedural assets unless the file
   gives a stiffness, so it stays where it is left.
7. **handles** by the heuristic of :mod:`asset_pipeline.handles`; **kinds** from PartNet-
   Mobility's ``semantics.txt`` label or the link and joint names (drawer, door, lid, rack,
   seat; knobs, buttons, switches, levers and wheels are flaps), else from the motion: a
   horizontal slide -> drawer, a vertical one -> lid when the part reaches the asset's top,
   else rack; an unlimited hinge -> flap; a vertical hinge -> door; a horizontal hinge -> lid
   when the part reaches the asset's top, else door.
8. **surfaces**: the carcass's upward surfaces (:func:`asset_pipeline.surfaces.support_surfaces`)
   that have carcass above them and a part in front are *interior* (``behind`` the joints of
   those parts), the others outer ``surfaces``; a part's upward surfaces with something above
   them at the closed pose (a drawer bottom) are interior surfaces of that part, behind its
   joint and its ancestors'. Interior surfaces with less than :data:`MIN_CLEARANCE_M` free above
   are left out. The free height (``clearance_m``) is measured at the closed pose.

Parts whose colliders overlap another body's (other than the one they hang on) at the closed
pose are reported in a warning: they would collide in the model. A file without moving joints
becomes a rigid asset (with a warning).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import trimesh

from asset_pipeline import annotate, physical
from asset_pipeline.articulated_bodies import (
    Body,
    Built,
    body_label,
    close_parts,
    normalised_bodies,
    opening_front,
    split_bodies,
)
from asset_pipeline.articulated_joints import (
    part_record,
    warn_touching,
)
from asset_pipeline.articulated_surfaces import (
    asset_surfaces,
)
from asset_pipeline.decompose import decompose
from asset_pipeline.hulls import collision_records, postprocess
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
    physical_record,
    source_digest,
    visual_records,
)
from asset_pipeline.kinematics import Kinematics
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.mjcf_import import check_mjcf, load_mjcf, mjcf_files, root_tag
from asset_pipeline.normalise import Front, Normalisation, UpAxis
from asset_pipeline.proximity import MeshProximity
from asset_pipeline.repair import repair
from asset_pipeline.urdf import read_urdf
from asset_pipeline.urdf_kinematics import load_urdf
from holomj.errors import FormatError

MAX_PART_SHARE = 0.8
# PartNet-Mobility's model_cat -> holomj category (others: snake_case of model_cat).
PARTNET_CATEGORIES = {
    "StorageFurniture": "cabinet",
    "Refrigerator": "fridge",
    "WashingMachine": "washing_machine",
    "TrashCan": "trash_can",
    "KitchenPot": "pot",
    "Display": "monitor",
    "FoldingChair": "chair",
    "Dispenser": "soap_dispenser",
}


def articulated_format(path: Path) -> str | None:
    """``"urdf"`` or ``"mjcf"`` when ``path`` is an articulated description file, else None."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".urdf":
        return "urdf"
    if suffix in (".xml", ".mjcf") and path.is_file():
        tag = root_tag(path)
        if tag == "mujoco":
            return "mjcf"
        if tag == "robot":
            return "urdf"
    return None


def check_articulated_file(path: Path) -> None:
    """Check the file's structure (URDF: its tree and that every mesh exists; MJCF: that
    MuJoCo loads it and its tree); a one-line FormatError naming file and element."""
    if articulated_format(path) == "mjcf":
        check_mjcf(Path(path))
    else:
        read_urdf(path)


def articulated_sources(path: Path) -> list[Path]:
    """The files an import of ``path`` reads besides itself (meshes, their materials and
    textures, PartNet-Mobility's ``meta.json`` and ``semantics.txt``), for cache keys."""
    path = Path(path)
    try:
        meshes = mjcf_files(path) if articulated_format(path) == "mjcf" else read_urdf(path).files()
    except FormatError:
        return []
    found: list[Path] = []
    for mesh in meshes:
        found.append(mesh)
        for companion in sorted(mesh.parent.glob(f"{mesh.stem}.*")):
            if companion.suffix.lower() in (".mtl", ".bin", ".png", ".jpg", ".jpeg"):
                found.append(companion)
    for extra in ("meta.json", "semantics.txt"):
        if (path.parent / extra).is_file():
            found.append(path.parent / extra)
    return list(dict.fromkeys(p for p in found if p != path))


def import_articulated(path: Path | str, asset_id: str, options: ImportOptions) -> ImportedAsset:
    """Import the URDF or MJCF file ``path`` as asset ``asset_id`` with ``options``; see the
    module docstring."""
    path = Path(path)
    check_asset_id(asset_id)
    timer = StepTimer()
    sidecar = Sidecar.of(path, options.sidecar)
    files: dict[str, bytes] = {}
    done = _processed(path, options, timer, files)
    kin, frame, built, warnings = done.kin, done.frame, done.built, done.warnings
    named = kin.category
    found = (_partnet_category(named), "PartNet-Mobility meta.json") if named else None
    category, category_source = chosen_category(path, options.category, sidecar, found)
    info = physical.category_info(category, frame.size)
    given, density = asked_mass(options.mass_kg, sidecar)
    volume = sum(sum(c.volume for c in b.colliders) for b in built)
    massed, masses = _masses(built, info, given, density)
    timer.lap("mass")

    asset_top = float(frame.size[2])
    part_records = [
        part_record(b, mass, kin, asset_top) for b, mass in zip(built[1:], masses[1:], strict=True)
    ]
    surfaces, interior = asset_surfaces(built, warnings)
    warn_touching(built, warnings)
    timer.lap("surfaces")

    derived = derived_meta(
        asset_id=asset_id,
        category=category,
        description=annotate.describe(category),
        size=frame.size,
        mass_kg=massed.mass_kg,
        density_kg_m3=density if density is not None else massed.mass_kg / volume,
        info=info,
        placement=info.placement,
        geometry={
            "visual": built[0].body.record["visual"],
            "collision": built[0].body.record["collision"],
            "maxhullvert": max(4, *(q.quality["max_vertices_per_hull"] for q in built)),
            "surfaces": surfaces,
        },
        source=f"{path.name} ({done.fmt}, up {done.up_axis}, front {done.front} -> +x, "
        f"scale {frame.scale:.6g})",
    )
    if part_records:
        derived["articulation"] = {"parts": part_records, "interior": interior}
    else:
        warnings.append("no moving joint: imported as a rigid asset")
    explicit = explicit_fields(options.category, options.description, options.mass_kg)
    meta, meta_warnings = annotate.build_meta(derived, sidecar.data, explicit, sidecar.where)
    timer.lap("annotate")
    warnings += massed.warnings + meta_warnings
    degraded = [
        f"{body_label(b.body)}: {b.decomposition.degraded_reason}"
        for b in built
        if b.decomposition.degraded
    ]
    if degraded:
        warnings.append(f"degraded decomposition: {'; '.join(degraded)}")
    report = {
        "asset_id": asset_id,
        "source": _source_report(path, done, sidecar),
        "normalisation": frame.as_report() | {"requested_size_m": options.size},
        "degraded": bool(degraded),
        "degraded_reason": "; ".join(degraded) or None,
        "bodies": [_body_report(b, mass) for b, mass in zip(built, masses, strict=True)],
        "surfaces": [{"height": s["height"], "area_m2": s["area_m2"]} for s in surfaces],
        "interior_surfaces": [
            {"part": s["part"], "height": s["height"], "behind": s["behind"]} for s in interior
        ],
        "physical": physical_record(meta, info, massed, category_source),
        "files": file_sizes(files),
        "timings_s": timer.timings,
        "warnings": warnings,
    }
    return ImportedAsset(bundle=AssetBundle(meta=meta, files=files), report=report)


@dataclass
class _ProcessedArticulation:
    """An articulated file after the geometry steps: its format and kinematic tree, the frame
    it was normalised into, every body built (the carcass first) and the warnings so far."""

    fmt: str
    kin: Kinematics
    up_axis: UpAxis
    front: Front
    frame: Normalisation
    built: list[Built]
    warnings: list[str]


def _processed(
    path: Path, options: ImportOptions, timer: StepTimer, files: dict[str, bytes]
) -> _ProcessedArticulation:
    """Load the file, split it into bodies at the closed pose, normalise them together and
    build each (repair, decomposition, visual and collision files into ``files``), timed."""
    where = str(path)
    fmt = articulated_format(path) or "urdf"
    kin = (
        load_mjcf(path, options.max_faces) if fmt == "mjcf" else load_urdf(path, options.max_faces)
    )
    warnings = list(kin.warnings)
    timer.lap("load")
    carcass, parts = split_bodies(kin, where, warnings)
    close_parts(parts, warnings)
    up_axis = options.up_axis or kin.up_axis
    front = options.front if options.front != "+x" else opening_front(parts, up_axis)
    everything = [carcass, *parts]
    frame = normalised_bodies(everything, where, up_axis, front, options.size)
    timer.lap("normalise")
    textures: dict[str, str] = {}
    built = [_build(body, options, files, textures, where) for body in everything]
    timer.lap("decompose")
    return _ProcessedArticulation(fmt, kin, up_axis, front, frame, built, warnings)


def _source_report(path: Path, done: _ProcessedArticulation, sidecar: Sidecar) -> dict[str, Any]:
    """The report's section on the file read."""
    kin = done.kin
    return {
        "file": str(path),
        "sha256": source_digest(path),
        "format": done.fmt,
        "partnet_mobility": kin.partnet,
        "links": len(kin.links),
        "joints": len(kin.joints),
        "vertices": kin.vertices,
        "faces": kin.faces,
        "sidecar": str(sidecar.path) if sidecar.path else None,
    }


def _body_report(built: Built, mass: float) -> dict[str, Any]:
    """The report's line of one body: its links, repairs, decomposition, quality, mass and
    (for a part) its joint."""
    return {
        "body": body_label(built.body),
        "links": built.body.links,
        "repairs": built.repaired.stats,
        "watertight": built.repaired.watertight,
        "decomposition": {
            "method": built.decomposition.method,
            "preprocess_mode": built.decomposition.preprocess_mode,
            "attempts": built.decomposition.attempts,
        },
        "quality": built.quality,
        "mass_kg": mass,
        **({"joint": built.body.record["joint_report"]} if built.body.joint else {}),
    }


# --- 1. bodies --------------------------------------------------------------------------------


# --- 2. closed pose ---------------------------------------------------------------------------


# --- 3. frame ---------------------------------------------------------------------------------


# --- 4. meshes and colliders per body ---------------------------------------------------------
def _build(
    body: Body, options: Any, files: dict[str, bytes], textures: dict[str, str], where: str
) -> Built:
    repaired = repair(body.parts)
    if len(repaired.physics.faces) == 0:
        raise FormatError(f"{body_label(body)}: the meshes have only degenerate faces", where=where)
    manifold = repaired.watertight and repaired.winding_consistent
    decomposition = decompose(repaired.physics, options.coacd, manifold)
    proximity = MeshProximity(repaired.physics)
    hullset = postprocess(decomposition.hulls, repaired.physics, proximity, repaired.watertight)
    prefix = f"{body.name}_" if body.name else ""
    visual = visual_records(repaired.visuals, files, textures, prefix)
    collision = collision_records(hullset.colliders, files, prefix)
    body.record.update(visual=visual, collision=collision)
    return Built(body, repaired, hullset.colliders, decomposition, hullset.quality)


# --- 5. mass ----------------------------------------------------------------------------------
def _masses(
    built: list[Built], info: physical.PhysicalDefaults, given: float | None, density: float | None
) -> tuple[physical.MassResult, list[float]]:
    """The whole asset's mass (as for a mesh import, over all bodies) and each body's share."""
    volumes = [sum(c.volume for c in b.colliders) for b in built]
    whole = trimesh.util.concatenate([b.repaired.physics for b in built])
    if not isinstance(whole, trimesh.Trimesh):  # the concatenation of meshes is a mesh
        raise TypeError("the bodies' physics meshes did not concatenate into one mesh")
    massed = physical.resolve_mass(info, whole, sum(volumes), given=given, density=density)
    return massed, _share_mass(massed.mass_kg, built, info, volumes)


def _share_mass(total: float, built: list[Built], info: Any, volumes: list[float]) -> list[float]:
    """The carcass's and every part's mass: ``total`` shared by material volume."""
    shares = [physical.material_volume(b.repaired.physics, info.wall_m).volume_m3 for b in built]
    if not all(math.isfinite(s) and s > 0 for s in shares):
        shares = volumes
    whole = sum(shares)
    masses = [total * s / whole for s in shares]
    moving = sum(masses[1:])
    if moving > MAX_PART_SHARE * total:
        masses[1:] = [m * MAX_PART_SHARE * total / moving for m in masses[1:]]
        masses[0] = total - sum(masses[1:])
    return [float(f"{m:.6g}") for m in masses]


# --- 6 and 7. joints, handles, kinds ----------------------------------------------------------


# --- 8. surfaces ------------------------------------------------------------------------------


def _partnet_category(model_cat: str) -> str:
    if model_cat in PARTNET_CATEGORIES:
        return PARTNET_CATEGORIES[model_cat]
    return re.sub(r"(?<!^)(?=[A-Z])", "_", model_cat).lower()
