"""Asset metadata and the on-disk asset library format.

A library is a folder::

    LIB/library.json               LibraryIndex: {"schema_version", "name", "assets": {id: folder}}
    LIB/<folder>/asset.json        AssetMeta (paths inside are relative to <folder>)
    LIB/<folder>/*.obj|*.stl|*.png visual meshes, convex collision hulls, textures, thumbnails

Asset frame: metres, Z up, origin at the centre of the footprint at the bottom, front facing +X.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import AfterValidator, Field, model_validator

from holomj.spec.base import FrozenModel, Identifier, PositiveFloat, Rgba, Vec2, Vec3, Vec4

ASSET_SCHEMA_VERSION = "1.0"
PLACEMENTS = ("floor", "wall", "object", "ceiling")


def _inside_folder(path: str) -> str:
    """Reject ``.``/``..`` and empty segments: files stay inside their asset folder."""
    if any(part in ("", ".", "..") for part in path.split("/")):
        raise ValueError(f"path {path!r} must stay inside the asset folder (no '.', '..' or '//')")
    return path


RelPath = Annotated[
    str,
    Field(min_length=1, max_length=512, pattern=r"^[A-Za-z0-9_][A-Za-z0-9_./\-]*$"),
    AfterValidator(_inside_folder),
]


class VisualPart(FrozenModel):
    """One visual mesh with one material (MuJoCo allows one material per mesh geom)."""

    mesh: RelPath = Field(description="OBJ or STL file inside the asset folder.")
    rgba: Rgba = (0.7, 0.7, 0.7, 1.0)
    texture: RelPath | None = Field(default=None, description="PNG; the mesh must carry UVs.")
    specular: Annotated[float, Field(ge=0.0, le=1.0)] = 0.3
    shininess: Annotated[float, Field(ge=0.0, le=1.0)] = 0.3


class CollisionPart(FrozenModel):
    """One convex collider: a convex hull mesh or a MuJoCo primitive.

    ``size`` uses MuJoCo's half-sizes: box (hx, hy, hz), cylinder and capsule (radius,
    half-length), sphere (radius). ``volume_m3`` is the collider's own volume (for mass).
    """

    kind: Literal["mesh", "box", "cylinder", "sphere", "capsule"]
    mesh: RelPath | None = None
    size: tuple[PositiveFloat, ...] = ()
    pos: Vec3 = (0.0, 0.0, 0.0)
    quat: Vec4 = (1.0, 0.0, 0.0, 0.0)
    volume_m3: Annotated[float, Field(gt=0.0)]

    @model_validator(mode="after")
    def _shape_fields(self) -> CollisionPart:
        expected = {"mesh": 0, "box": 3, "cylinder": 2, "capsule": 2, "sphere": 1}[self.kind]
        if self.kind == "mesh" and self.mesh is None:
            raise ValueError("a mesh collider needs 'mesh'")
        if self.kind != "mesh" and len(self.size) != expected:
            raise ValueError(f"a {self.kind} collider needs {expected} size values")
        if math.sqrt(sum(q * q for q in self.quat)) < 1e-9:
            raise ValueError("quaternion has zero length")
        return self


class SupportSurface(FrozenModel):
    """An upward-facing surface small objects may rest on, in the asset frame."""

    height: float = Field(description="z of the surface in the asset frame, metres.")
    polygon: list[Vec2] = Field(min_length=3)
    area_m2: Annotated[float, Field(gt=0.0)]


class AssetMeta(FrozenModel):
    """Everything the compiler and the planners need to know about one asset."""

    schema_version: Literal["1.0"] = ASSET_SCHEMA_VERSION
    id: Identifier
    category: str = Field(min_length=1, max_length=64)
    description: str = ""
    size: tuple[PositiveFloat, PositiveFloat, PositiveFloat] = Field(
        description="Axis-aligned bounding box extent (x, y, z), metres."
    )
    mass_kg: PositiveFloat | None = Field(
        default=None, description="Given mass; otherwise density times collision volume."
    )
    density_kg_m3: PositiveFloat = 500.0
    friction: Annotated[float, Field(gt=0.0, le=5.0)] = 0.8
    placement: list[Literal["floor", "wall", "object", "ceiling"]] = Field(
        default_factory=lambda: ["floor"]
    )
    front: Literal["+x"] = "+x"
    upright: bool = Field(
        default=False, description="Must stand upright when placed (a mug, a vase, a bottle)."
    )
    visual: list[VisualPart] = Field(min_length=1)
    collision: list[CollisionPart] = Field(min_length=1)
    maxhullvert: Annotated[int, Field(ge=4, le=1024)] = 64
    surfaces: list[SupportSurface] = Field(default_factory=list)
    thumbnails: list[RelPath] = Field(default_factory=list)
    source: str | None = None
    license: str | None = None
    attribution: str | None = None
    attributes: dict[str, str] = Field(
        default_factory=dict,
        description="Colour, material, shape and style the asset was built with (procedural "
        "synthesis on demand); empty when not recorded.",
    )
    proxy: bool = Field(
        default=False,
        description="A stand-in built from a parametric family (box, slab on legs, column...) "
        "for a category no library asset or generator supplies; labelled with that category.",
    )
    collider_gap_m: Annotated[float, Field(ge=0.0)] | None = Field(
        default=None,
        description="Largest distance from a point of the visual surface to the union of the "
        "colliders, metres (asset_pipeline.collider_audit); None when not measured.",
    )

    @property
    def collision_volume_m3(self) -> float:
        """Total volume of the colliders (overlaps counted twice)."""
        return sum(part.volume_m3 for part in self.collision)

    @property
    def mass(self) -> float:
        """Mass in kg at scale 1."""
        if self.mass_kg is not None:
            return self.mass_kg
        return self.density_kg_m3 * self.collision_volume_m3


class LibraryIndex(FrozenModel):
    """``library.json``: the assets of a library and their folders."""

    schema_version: Literal["1.0"] = ASSET_SCHEMA_VERSION
    name: str = "library"
    assets: dict[Identifier, RelPath] = Field(default_factory=dict)
