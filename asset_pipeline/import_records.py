"""What the importers share: the import options and result, the bundle's visual and physical
records, and the asset id check (:mod:`asset_pipeline.importer` for mesh files,
:mod:`asset_pipeline.articulated_import` for URDF and MJCF files and
:mod:`asset_pipeline.objathor_import` for objathor directories).
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from pydantic import TypeAdapter, ValidationError

from asset_pipeline import physical
from asset_pipeline.decompose import CoacdParams
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.objfile import obj_bytes
from holomj.errors import SpecError
from holomj.spec.assets import AssetMeta
from holomj.spec.base import Identifier


@dataclass(frozen=True)
class ImportOptions:
    """How to import a file (see the module docstring for the steps)."""

    category: str | None = None  # else guessed from the file name, else "object"
    size: tuple[float, float, float] | None = None  # uniform scale to fit inside this box (m)
    description: str | None = None
    mass_kg: float | None = None
    up_axis: Literal["y", "z"] | None = None  # None: "y" for glTF/GLB, "z" otherwise
    front: Literal["+x", "-x", "+y", "-y"] = "+x"  # source axis (after up-conversion) = front
    sidecar: Path | None = None  # default: <file>.holomj.json / .yaml next to it, if present
    coacd: CoacdParams = field(default_factory=CoacdParams)
    max_faces: int = 2_000_000


@dataclass(frozen=True)
class ImportedAsset:
    """An imported asset: its bundle (meta and files, nothing written yet) and its report."""

    bundle: AssetBundle
    report: dict


def visual_records(
    visuals: Sequence[Any], files: dict[str, bytes], textures: dict[str, str], prefix: str = ""
) -> list[dict[str, Any]]:
    """The ``visual`` records of repaired visual meshes; each mesh's OBJ goes into ``files`` as
    ``{prefix}visual_K.obj`` and each distinct texture once as ``texture_N.png`` (``textures``:
    its sha256 -> file name, shared by the calls for one asset)."""
    visual: list[dict[str, Any]] = []
    for k, mesh in enumerate(visuals):
        name = f"{prefix}visual_{k}.obj"
        files[name] = obj_bytes(mesh.vertices, mesh.faces, mesh.uv)
        entry: dict[str, Any] = {"mesh": name, "rgba": list(mesh.material.rgba)}
        if mesh.material.texture_png is not None:
            digest = hashlib.sha256(mesh.material.texture_png).hexdigest()
            if digest not in textures:
                textures[digest] = f"texture_{len(textures)}.png"
                files[textures[digest]] = mesh.material.texture_png
            entry["texture"] = textures[digest]
        visual.append(entry)
    return visual


def physical_record(
    meta: AssetMeta,
    info: physical.CategoryInfo,
    massed: physical.MassResult,
    category_source: str,
) -> dict[str, Any]:
    """The ``physical`` section of an import's ``derivation.json``: the category and where it
    came from, the mass and how it was derived, the material, friction and uprightness."""
    return {
        "category": meta.category,
        "category_source": category_source,
        "category_known": info.known,
        "density_kg_m3": meta.density_kg_m3,
        "mass_kg": meta.mass,
        "mass_source": massed.source,
        "mass_range_kg": list(info.mass_range_kg),
        "material": info.material,
        "mass_derivation": massed.derivation,
        "upright": info.upright,
        "friction": meta.friction,
    }


def check_asset_id(asset_id: str) -> None:
    """Raise SpecError unless ``asset_id`` is a valid asset id."""
    try:
        TypeAdapter(Identifier).validate_python(asset_id)
    except ValidationError:
        raise SpecError(
            f"invalid asset id {asset_id!r}",
            where="asset_id",
            fix="use letters, digits and _ . : | + - (not starting with a symbol)",
        ) from None
