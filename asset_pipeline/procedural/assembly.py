"""Turn a parametric asset design (parts + facts) into a library :class:`AssetBundle`.

The design may be drawn in any frame; assembly moves it so that the bounding box of the
visual meshes is centred on the origin in X and Y with its bottom at z = 0 (the asset frame of
holomj), merges the parts of each material into one OBJ, and derives colliders, support
surfaces, size and density.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural.obj_writer import merge_meshes, obj_bytes, rounded
from asset_pipeline.procedural.parts import Collider, Material, Part, Surface, Vec3
from holomj.spec.assets import AssetMeta, CollisionPart, SupportSurface, VisualPart
from holomj.spec.base import validate_model

SOURCE = "holomj procedural"
LICENSE = "Apache-2.0"
DECIMALS = 6  # metadata numbers (OBJ vertices use 5)


@dataclass(frozen=True)
class AssetDesign:
    """Everything needed to build one procedural asset."""

    id: str
    category: str
    description: str
    mass_kg: float
    friction: float
    placement: tuple[str, ...]
    parts: tuple[Part, ...]
    attributes: tuple[tuple[str, str], ...] = ()  # honoured (colour, material, shape, style)
    proxy: bool = False  # a stand-in from a parametric family (asset_pipeline.procedural.proxies)


CLEARANCE = 0.05  # free height required above every support surface
PROUD = 1e-3  # parts standing less than this above a surface (tape, a screen) do not block it


# Small objects that only make sense standing (spawn-and-drop rejects them tipped over).
UPRIGHT_CATEGORIES = frozenset(
    {
        "mug",
        "cup",
        "bowl",
        "bottle",
        "vase",
        "candle",
        "small_plant",
        "potted_plant",
        "desk_lamp",
        "floor_lamp",
        "pot",
        "laptop",
    }
)


def assemble(design: AssetDesign, expected_size: Vec3 | None = None) -> AssetBundle:
    """Build the bundle (metadata + OBJ files) of ``design``.

    With ``expected_size`` the visual bounding box must match it within 1 mm. Every support
    surface must have :data:`CLEARANCE` of free space above it (no part's bounds reach into
    the prism over its polygon); a violation is a bug in the design and raises ValueError.
    """
    parts = centred_parts(design.parts)
    by_material: dict[str, tuple[Material, list]] = {}
    for part in parts:
        mesh = part.mesh()
        if mesh is not None:
            by_material.setdefault(part.material.name, (part.material, []))[1].append(mesh)
    files: dict[str, bytes] = {}
    visual = []
    all_vertices = []
    for name in sorted(by_material):
        material, meshes = by_material[name]
        mesh = rounded(merge_meshes(meshes))
        all_vertices.append(mesh.vertices)
        filename = f"{name}.obj"
        files[filename] = obj_bytes(mesh, comment=f"{design.id}: {name} ({SOURCE}, {LICENSE})")
        visual.append(
            VisualPart(
                mesh=filename,
                rgba=material.rgba,
                specular=material.specular,
                shininess=material.shininess,
            )
        )
    vertices = np.concatenate(all_vertices)
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    if expected_size is not None and np.any(np.abs(high - low - expected_size) > 1e-3):
        raise ValueError(
            f"{design.id}: generated size {tuple(np.round(high - low, 4))} differs from the "
            f"requested {expected_size}"
        )
    colliders = [c for part in parts for c in part.colliders()]
    _check_inside(design.id, colliders, low, high)
    _check_clearance(design.id, parts)
    collision = [_collision_part(c) for c in colliders]
    volume = sum(c.volume_m3 for c in collision)
    surfaces = [_support_surface(s) for part in parts for s in part.surfaces()]
    surfaces.sort(key=lambda s: (s.height, s.polygon))
    meta = {
        "id": design.id,
        "category": design.category,
        "description": design.description,
        "size": [_r(v) for v in high - low],
        "mass_kg": design.mass_kg,
        "density_kg_m3": round(design.mass_kg / volume, 3),
        "friction": design.friction,
        "placement": list(design.placement),
        "upright": design.category in UPRIGHT_CATEGORIES,
        "visual": [v.model_dump(mode="json") for v in visual],
        "collision": [c.model_dump(mode="json") for c in collision],
        "surfaces": [s.model_dump(mode="json") for s in surfaces],
        "source": SOURCE,
        "license": LICENSE,
    }
    if design.attributes:
        meta["attributes"] = dict(design.attributes)
    if design.proxy:
        meta["proxy"] = True
    return AssetBundle(meta=validate_model(AssetMeta, meta, design.id), files=files)


def assemble_all(designs: Sequence[AssetDesign]) -> list[AssetBundle]:
    """Assemble every design, in order."""
    return [assemble(design) for design in designs]


def centred_parts(parts: Sequence[Part]) -> list[Part]:
    """The parts moved into the asset frame: visual bbox centred in X, Y, bottom at z = 0."""
    bounds = [b for b in (p.bounds() for p in parts) if b is not None]
    if not bounds:
        raise ValueError("a design needs at least one visual part")
    low = np.min([b[0] for b in bounds], axis=0)
    high = np.max([b[1] for b in bounds], axis=0)
    offset: Vec3 = (
        -0.5 * float(low[0] + high[0]),
        -0.5 * float(low[1] + high[1]),
        -float(low[2]),
    )
    return [p.translated(offset) for p in parts]


def _check_inside(asset_id: str, colliders: list[Collider], low: np.ndarray, high: np.ndarray):
    tol = 2e-5
    for collider in colliders:
        half = np.asarray(collider.half_extents())
        pos = np.asarray(collider.pos)
        if np.any(pos - half < low - tol) or np.any(pos + half > high + tol):
            raise ValueError(f"{asset_id}: collider {collider} sticks out of the visual bounds")


def _part_boxes(part: Part) -> list[tuple[np.ndarray, np.ndarray]]:
    boxes = []
    bounds = part.bounds()
    if bounds is not None:
        boxes.append((np.asarray(bounds[0]), np.asarray(bounds[1])))
    for c in part.colliders():
        half = np.asarray(c.half_extents())
        boxes.append((np.asarray(c.pos) - half, np.asarray(c.pos) + half))
    return boxes


def _check_clearance(asset_id: str, parts: Sequence[Part]) -> None:
    boxes = [box for part in parts for box in _part_boxes(part)]
    for part in parts:
        for surface in part.surfaces():
            xy = np.asarray(surface.polygon)
            (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
            h = surface.height
            for low, high in boxes:
                if (
                    high[2] > h + PROUD
                    and low[2] < h + CLEARANCE
                    and low[0] < x1 - 1e-6
                    and high[0] > x0 + 1e-6
                    and low[1] < y1 - 1e-6
                    and high[1] > y0 + 1e-6
                ):
                    raise ValueError(
                        f"{asset_id}: the surface at z = {h:.3f} has a part within "
                        f"{CLEARANCE} m above it ({np.round(low, 3)}..{np.round(high, 3)})"
                    )


def _collision_part(collider: Collider) -> CollisionPart:
    size = tuple(_r(v) for v in collider.size)
    rounded = Collider(collider.kind, size, collider.pos, collider.axis)
    return CollisionPart(
        kind=collider.kind,
        size=size,
        pos=tuple(_r(v) for v in collider.pos),
        quat=tuple(_r(v) for v in collider.quat),
        volume_m3=float(f"{rounded.volume:.9g}"),
    )


def _support_surface(surface: Surface) -> SupportSurface:
    polygon = [(_r(x), _r(y)) for x, y in surface.polygon]
    area = 0.0
    for (x0, y0), (x1, y1) in zip(polygon, polygon[1:] + polygon[:1], strict=True):
        area += x0 * y1 - x1 * y0
    return SupportSurface(height=_r(surface.height), polygon=polygon, area_m2=_r(0.5 * area))


def _r(value: float) -> float:
    """Round a metadata number; never ``-0.0``."""
    return round(float(value), DECIMALS) + 0.0
