"""What every import shares (a mesh file, an articulated URDF/MJCF file, an objathor asset): the
result type, the asset id check, the step timer, the sidecar, the category choice, and the
records it writes into the asset's metadata and its ``derivation.json`` report."""

from __future__ import annotations

import hashlib
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from pydantic import TypeAdapter, ValidationError

from asset_pipeline import annotate, physical
from asset_pipeline.decompose import CoacdParams
from asset_pipeline.hulls import HullSet, collision_records
from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.objfile import obj_bytes
from holomj.errors import SpecError
from holomj.spec.assets import AssetMeta
from holomj.spec.base import Identifier

ID_FIX = "use letters, digits and _ . : | + - (not starting with a symbol)"


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
    """An imported asset: its bundle (metadata and files) and the report of how it was made."""

    bundle: AssetBundle
    report: dict[str, Any]


def check_asset_id(asset_id: str, where: str = "asset_id", fix: str = ID_FIX) -> None:
    """A SpecError unless ``asset_id`` is a valid asset identifier."""
    try:
        TypeAdapter(Identifier).validate_python(asset_id)
    except ValidationError:
        raise SpecError(f"invalid asset id {asset_id!r}", where=where, fix=fix) from None


class StepTimer:
    """Seconds spent per step of an import: :meth:`lap` closes the step running since the last
    lap (or since the timer was made) under a name."""

    def __init__(self) -> None:
        self.timings: dict[str, float] = {}
        self._clock = time.perf_counter()

    def lap(self, name: str) -> None:
        """Record the time since the last lap as step ``name``."""
        now = time.perf_counter()
        self.timings[name] = round(now - self._clock, 3)
        self._clock = now


@dataclass(frozen=True)
class Sidecar:
    """The sidecar annotations of an imported file (see :mod:`asset_pipeline.annotate`): the
    file (None: there is none), what it says, and where its errors point."""

    path: Path | None
    data: dict[str, Any]
    where: str

    @classmethod
    def of(cls, source: Path, chosen: Path | None) -> Sidecar:
        """The sidecar ``chosen`` (an import option), else the default one next to ``source``."""
        path = chosen if chosen is not None else annotate.find_sidecar(source)
        if not path:
            return cls(None, {}, str(source))
        return cls(Path(path), annotate.read_sidecar(Path(path)), str(path))

    def number(self, key: str) -> float | None:
        """The sidecar's number ``key``, or None (a FormatError when it is not a number)."""
        return annotate.sidecar_number(self.data, key, self.where)


def chosen_category(
    source: Path, option: str | None, sidecar: Sidecar, found: tuple[str, str] | None = None
) -> tuple[str, str]:
    """(category, where it came from): the import option, else the sidecar's, else ``found``
    (a category the file itself names, with its source), else one guessed from the file name,
    else the default category."""
    if option:
        return option, "option"
    if sidecar.data.get("category"):
        return str(sidecar.data["category"]), "sidecar"
    if found is not None:
        return found
    guessed = physical.guess_category(source)
    if guessed:
        return guessed, "file name"
    return physical.DEFAULT_CATEGORY, "default"


def asked_mass(mass_option: float | None, sidecar: Sidecar) -> tuple[float | None, float | None]:
    """(the mass asked, the density asked): the option's mass, else the sidecar's; the
    sidecar's density."""
    given = mass_option if mass_option is not None else sidecar.number("mass_kg")
    return given, sidecar.number("density_kg_m3")


def explicit_fields(
    category: str | None, description: str | None, mass_kg: float | None
) -> dict[str, Any]:
    """The metadata fields the import options set, which win over the sidecar's."""
    explicit: dict[str, Any] = {"category": category, "description": description}
    if mass_kg is not None:
        explicit["mass_kg"] = float(mass_kg)
    return explicit


def derived_meta(
    *,
    asset_id: str,
    category: str,
    description: str,
    size: Sequence[float],
    mass_kg: float,
    density_kg_m3: float,
    info: physical.PhysicalDefaults,
    placement: Sequence[str],
    geometry: dict[str, Any],
    source: str,
) -> dict[str, Any]:
    """The metadata an import derives (before the sidecar and the options have their say);
    ``geometry`` holds the ``visual``, ``collision``, ``maxhullvert`` and ``surfaces``
    records."""
    return {
        "id": asset_id,
        "category": category,
        "description": description,
        "size": list(size),
        "mass_kg": mass_kg,
        # The density of the collision volume that gives this mass (AssetMeta's meaning).
        "density_kg_m3": density_kg_m3,
        "friction": info.friction,
        "placement": list(placement),
        "upright": info.upright,
        "front": "+x",
        **geometry,
        "source": source,
    }


def mesh_geometry(
    visuals: Sequence[Any], hullset: HullSet, surfaces: Sequence[Any], files: dict[str, bytes]
) -> dict[str, Any]:
    """The metadata records of a one-body asset's geometry (``visual``, ``collision``,
    ``maxhullvert``, ``surfaces``); the visual and hull OBJ files go into ``files``."""
    return {
        "visual": visual_records(visuals, files, {}),
        "collision": collision_records(hullset.colliders, files),
        "maxhullvert": hullset.maxhullvert,
        "surfaces": surface_records(surfaces),
    }


def surface_records(surfaces: Sequence[Any]) -> list[dict[str, Any]]:
    """The metadata records of support surfaces (height, polygon, area)."""
    return [
        {"height": s.height, "polygon": [list(p) for p in s.polygon], "area_m2": s.area}
        for s in surfaces
    ]


def surface_summary(surfaces: Sequence[Any]) -> list[dict[str, Any]]:
    """The report's lines of support surfaces (height and area)."""
    return [{"height": s.height, "area_m2": s.area} for s in surfaces]


def file_sizes(files: dict[str, bytes]) -> dict[str, int]:
    """The report's file list: name -> bytes, sorted by name."""
    return {name: len(data) for name, data in sorted(files.items())}


def source_digest(path: Path) -> str:
    """sha256 of the imported file (the report's record of what was read)."""
    return hashlib.sha256(path.read_bytes()).hexdigest()


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
    info: physical.PhysicalDefaults,
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
