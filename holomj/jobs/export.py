"""The export job (``holomj export OUT --format glb|usd|urdf``): a scene folder in other formats.

The folder's ``scene.xml`` is loaded as users load it and exported at its initial state (the
poses of ``objects.json``) by :mod:`holomj.formats.glb`, :mod:`holomj.formats.usd` or
:mod:`holomj.formats.urdf`; the folder's ``scene.json`` says which bodies are which objects, rooms
and openings. Where it goes (``target``; default under ``OUT/export/``):

- ``glb``: one file ending in ``.glb`` (default ``OUT/export/scene.glb``).
- ``usd``: ``.usdz`` (default ``OUT/export/scene.usdz``: one package with its textures), or
  ``.usd`` / ``.usdc`` (binary) / ``.usda`` (text) with its textures in ``textures/`` beside it.
- ``urdf``: a folder (default ``OUT/export/urdf/``) with one ``<asset>/<asset>.urdf`` and its
  ``meshes/`` per articulated asset (doors, jointed furniture); empty when there is none.

Writes are atomic: a file is built beside its target and renamed over it, the URDF folder is
replaced as a whole, so a failure leaves the previous export as it was. Bad input (not a
holomj folder, an unknown format, a target of the wrong kind, usd-core missing) raises
:class:`~holomj.errors.InputError` before anything is written.
"""

from __future__ import annotations

import os
import re
import shutil
import tempfile
import time
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

from holomj.atomic import replace_folder, write_file
from holomj.errors import ExportError, InputError
from holomj.file_names import OBJECTS_JSON, SCENE_XML
from holomj.jobs.folder import read_json_report, read_scene
from holomj.jobs.folder import require_scene_folder as _require_scene_folder
from holomj.spec.export_details import ExportDetails, GlbDetails, UrdfDetails, UsdDetails

FORMATS = ("glb", "usd", "urdf")
EXPORT_DIR = "export"
USD_SUFFIXES = (".usdz", ".usd", ".usdc", ".usda")
_DEFAULT_NAMES = {"glb": "scene.glb", "usd": "scene.usdz", "urdf": "urdf"}
_UNSAFE = re.compile(r"[^A-Za-z0-9_.\-]")


@dataclass
class ExportResult:
    """What :func:`export_folder` wrote: the format, the target, every file (relative to the
    target's folder for glb and usd, to the target for urdf), sizes and timings."""

    folder: str
    format: str
    target: str
    files: list[str]
    bytes: int
    timings_s: dict[str, float] = field(default_factory=dict)
    details: ExportDetails | None = None  # None until the format's writer ran

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form (``details``: the format's, ``{}`` before it ran)."""
        details = {} if self.details is None else self.details.model_dump()
        return {**asdict(replace(self, details=None)), "details": details}


def default_target(out: Path, fmt: str) -> Path:
    """Where ``fmt`` goes when no target is given."""
    return Path(out) / EXPORT_DIR / _DEFAULT_NAMES[fmt]


def export_folder(
    out: Path,
    fmt: str,
    target: Path | None = None,
    *,
    colliders: bool = False,
) -> ExportResult:
    """Export the holomj folder ``out`` as ``fmt`` into ``target`` (see module docstring).

    ``colliders`` (glb only): also the collision-only geoms, as ``<id>/colliders`` nodes.
    """
    out = Path(out)
    fmt = _check_format(fmt)
    folder = _require_scene_folder(out, "holomj compile' or 'holomj generate")
    target = Path(target) if target is not None else default_target(folder, fmt)
    _check_target(target, fmt)
    if colliders and fmt != "glb":
        raise InputError(
            "--colliders applies to --format glb only",
            fix="USD and URDF always carry the colliders",
        )
    if fmt == "usd":
        from holomj.formats.usd import load_pxr

        load_pxr()  # a missing extra is bad input: say so before any work
    clock = time.perf_counter()
    from holomj.mjcf.loading import load_model_file

    model = load_model_file(folder / SCENE_XML)
    scene = read_scene(folder)
    timings = {"load": time.perf_counter() - clock}
    result = ExportResult(str(folder), fmt, str(target), [], 0)
    try:
        if fmt == "glb":
            _export_glb(folder, model, scene, target, colliders, result, timings)
        elif fmt == "usd":
            _export_usd(model, scene, target, result, timings)
        else:
            _export_urdf(model, scene, target, result, timings)
    except OSError as err:
        raise ExportError(
            f"writing the {fmt} export failed: {err.strerror or err}", where=str(target)
        ) from None
    timings["total"] = time.perf_counter() - clock
    result.timings_s = {k: round(v, 4) for k, v in timings.items()}
    return result


def _check_format(fmt: str) -> str:
    value = str(fmt).strip().lower()
    if value not in FORMATS:
        raise InputError(
            f"unknown export format {fmt!r}", where="--format", fix="choose glb, usd or urdf"
        )
    return value


def _check_target(target: Path, fmt: str) -> None:
    suffix = target.suffix.lower()
    if fmt == "glb" and suffix != ".glb":
        raise InputError(
            "a GLB export must be a file ending in .glb", where=str(target), fix="e.g. -o scene.glb"
        )
    if fmt == "usd" and suffix not in USD_SUFFIXES:
        raise InputError(
            "a USD export must be a file ending in .usdz, .usd, .usdc or .usda",
            where=str(target),
            fix="e.g. -o scene.usdz (one file with its textures)",
        )
    if fmt in ("glb", "usd") and target.is_dir():
        raise InputError("is a folder", where=str(target), fix="name the file to write")
    if fmt == "urdf" and target.exists() and not target.is_dir():
        raise InputError(
            "a URDF export is a folder, and this is a file", where=str(target), fix="name a folder"
        )


def _export_glb(
    folder: Path,
    model: Any,
    scene: Any,
    target: Path,
    colliders: bool,
    result: ExportResult,
    timings: dict[str, float],
) -> None:
    from holomj.formats.glb import scene_glb

    clock = time.perf_counter()
    data = scene_glb(model, scene, colliders=colliders, object_info=_object_info(folder))
    timings["build"] = time.perf_counter() - clock
    clock = time.perf_counter()
    target.parent.mkdir(parents=True, exist_ok=True)
    write_file(target, data)
    timings["write"] = time.perf_counter() - clock
    result.files = [target.name]
    result.bytes = len(data)
    result.details = GlbDetails(colliders=colliders)


def _object_info(folder: Path) -> dict[str, dict[str, Any]]:
    """Category and mass per object id from ``objects.json`` (empty when it is absent)."""
    record = read_json_report(folder, OBJECTS_JSON)
    if not isinstance(record, dict):
        return {}
    out = {}
    for entry in record.get("objects") or []:
        if isinstance(entry, dict) and isinstance(entry.get("id"), str):
            out[entry["id"]] = {key: entry[key] for key in ("category", "mass_kg") if key in entry}
    return out


def _export_usd(
    model: Any, scene: Any, target: Path, result: ExportResult, timings: dict[str, float]
) -> None:
    from pxr import Sdf, UsdUtils

    from holomj.formats.usd import scene_stage

    clock = time.perf_counter()
    usd = scene_stage(model, scene)
    timings["build"] = time.perf_counter() - clock
    clock = time.perf_counter()
    parent = target.parent
    parent.mkdir(parents=True, exist_ok=True)
    # (no ".usdz" in the folder name: USD would take it for a package)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.stem}-usd-", dir=parent))
    try:
        package = target.suffix.lower() == ".usdz"
        layer = tmp / ("scene.usdc" if package else target.name)
        if not usd.stage.GetRootLayer().Export(str(layer)):
            raise ExportError("USD could not write the stage", where=str(target))
        for name, data in usd.textures.items():
            path = tmp / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(data)
        if package:
            packed = tmp / "package.usdz"
            if not UsdUtils.CreateNewUsdzPackage(Sdf.AssetPath(str(layer)), str(packed)):
                raise ExportError("USD could not write the usdz package", where=str(target))
            os.replace(packed, target)
            result.files = [target.name]
        else:
            for name in sorted(usd.textures):  # textures first: the layer names them
                destination = parent / name
                destination.parent.mkdir(parents=True, exist_ok=True)
                os.replace(tmp / name, destination)
            os.replace(layer, target)
            result.files = [target.name, *sorted(usd.textures)]
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    timings["write"] = time.perf_counter() - clock
    result.bytes = sum((parent / f).stat().st_size for f in result.files)
    stage = usd.stage
    from pxr import UsdPhysics

    prims = list(stage.Traverse())
    result.details = UsdDetails(
        prims=len(prims),
        rigid_bodies=sum(p.HasAPI(UsdPhysics.RigidBodyAPI) for p in prims),
        colliders=sum(p.HasAPI(UsdPhysics.CollisionAPI) for p in prims),
        joints=sum(p.IsA(UsdPhysics.Joint) for p in prims),
        textures=len(usd.textures),
        notes=list(usd.notes),
    )


def _export_urdf(
    model: Any, scene: Any, target: Path, result: ExportResult, timings: dict[str, float]
) -> None:
    from holomj.formats.urdf import articulated_urdfs

    clock = time.perf_counter()
    urdfs = articulated_urdfs(model, scene)
    timings["build"] = time.perf_counter() - clock
    clock = time.perf_counter()
    files: dict[str, bytes] = {}
    taken: set[str] = set()
    assets = []
    for urdf in urdfs:
        name = _folder_name(urdf.asset_id, taken)
        files[f"{name}/{name}.urdf"] = urdf.urdf.encode("utf-8")
        for relative, data in urdf.meshes.items():
            files[f"{name}/{relative}"] = data
        assets.append(
            {
                "id": urdf.asset_id,
                "urdf": f"{name}/{name}.urdf",
                "joints": [
                    {"name": j, "type": t, "lower": lo, "upper": hi} for j, t, lo, hi in urdf.joints
                ],
            }
        )

    def fill(tmp: Path) -> None:
        for relative, data in files.items():
            path = tmp / relative
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(data)

    replace_folder(target, fill)
    timings["write"] = time.perf_counter() - clock
    result.files = sorted(files)
    result.bytes = sum(len(d) for d in files.values())
    result.details = UrdfDetails(assets=assets)


def _folder_name(asset_id: str, taken: set[str]) -> str:
    base = _UNSAFE.sub("_", asset_id) or "asset"
    name, index = base, 1
    while name in taken:
        name = f"{base}_{index}"
        index += 1
    taken.add(name)
    return name
