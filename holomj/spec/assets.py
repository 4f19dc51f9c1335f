"""Asset metadata and the on-disk asset library format.

A library is a folder::

    LIB/library.json               LibraryIndex: {"schema_version", "name", "assets": {id: folder}}
    LIB/<folder>/asset.json        AssetMeta (paths inside are relative to <folder>)
    LIB/<folder>/*.obj|*.stl|*.png visual meshes, convex collision hulls, textures, thumbnails

Asset frame: metres, Z up, origin at the centre of the footprint at the bottom, front facing +X.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Final, Literal

from pydantic import AfterValidator, Field, model_serializer, model_validator

from holomj.spec.base import FrozenModel, Identifier, PositiveFloat, Rgba, Vec2, Vec3, Vec4

ASSET_SCHEMA_VERSION: Final = "1.0"
PLACEMENTS = ("floor", "wall", "object", "ceiling")
Placement = Literal["floor", "wall", "object", "ceiling"]


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


# --- articulation ----------------------------------------------------------------------------
JointType = Literal["hinge", "slide"]
PartKind = Literal["door", "drawer", "lid", "seat", "rack", "flap"]
ArticulationName = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[A-Za-z0-9_]+$")]
NonNegative = Annotated[float, Field(ge=0.0)]


def _unit(vector: tuple[float, float, float], what: str) -> tuple[float, float, float]:
    length = math.sqrt(sum(v * v for v in vector))
    if length < 1e-9:
        raise ValueError(f"{what} has zero length")
    return (vector[0] / length, vector[1] / length, vector[2] / length)


class ArticulationJoint(FrozenModel):
    """The joint that moves one part of an articulated asset, in the asset frame.

    ``hinge``: rotation about ``axis`` through ``anchor``, values in radians; ``slide``:
    translation along ``axis``, values in metres (``anchor`` is a point of the part). Positive
    values open. The part's geometry is given at the value ``closed`` (the model's default
    pose, ``qpos0``). ``stiffness`` and ``springref`` make a spring (a counterbalance: an oven
    door's, a chest lid's), ``damping``, ``frictionloss`` and ``armature`` as MuJoCo's.
    """

    name: ArticulationName
    type: JointType
    axis: Vec3
    anchor: Vec3 = (0.0, 0.0, 0.0)
    range: tuple[float, float]
    closed: float = 0.0
    damping: NonNegative = 0.0
    frictionloss: NonNegative = 0.0
    armature: NonNegative = 0.0
    stiffness: NonNegative = 0.0
    springref: float = 0.0

    @model_validator(mode="after")
    def _limits(self) -> ArticulationJoint:
        object.__setattr__(self, "axis", _unit(self.axis, "axis"))
        low, high = self.range
        if not low < high:
            raise ValueError(f"range {self.range} must be (low, high) with low < high")
        if not low - 1e-9 <= self.closed <= high + 1e-9:
            raise ValueError(f"closed value {self.closed} lies outside the range {self.range}")
        if self.type == "hinge" and max(abs(low), abs(high)) > 2 * math.pi:
            raise ValueError("a hinge range is in radians and within one turn")
        return self


class Handle(FrozenModel):
    """Where a hand grasps a moving part, in the asset frame at the closed pose.

    ``pos`` is the middle of the grip; the grasp frame ``quat`` has its x axis along ``pull``
    (the direction a hand pulls to open, away from the front) and its z axis along the grip
    (a bar's long axis). ``length_m`` is the grip's length.
    """

    pos: Vec3
    quat: Vec4 = (1.0, 0.0, 0.0, 0.0)
    pull: Vec3 = (1.0, 0.0, 0.0)
    length_m: NonNegative = 0.0

    @model_validator(mode="after")
    def _unit_pull(self) -> Handle:
        object.__setattr__(self, "pull", _unit(self.pull, "pull"))
        if math.sqrt(sum(q * q for q in self.quat)) < 1e-9:
            raise ValueError("quaternion has zero length")
        return self


class ArticulatedPart(FrozenModel):
    """A moving part (door, drawer, lid, ...): its own body, joined to ``parent`` (None: the
    asset's carcass, else an earlier part) by ``joint``. Its ``visual`` and ``collision`` are
    given in the asset frame at the closed pose; ``mass_kg`` is its share of the asset's mass."""

    name: ArticulationName
    kind: PartKind
    parent: ArticulationName | None = None
    joint: ArticulationJoint
    mass_kg: PositiveFloat
    visual: list[VisualPart] = Field(min_length=1)
    collision: list[CollisionPart] = Field(min_length=1)
    handle: Handle | None = None

    @property
    def collision_volume_m3(self) -> float:
        """Total volume of the part's colliders."""
        return sum(c.volume_m3 for c in self.collision)


class InteriorSurface(FrozenModel):
    """An upward surface inside an articulated asset (a shelf behind a door, a drawer bottom),
    in the asset frame at the closed pose. ``part`` names the moving part it belongs to (None:
    the carcass); ``behind`` the joints that must open to reach it."""

    height: float
    polygon: list[Vec2] = Field(min_length=3)
    area_m2: Annotated[float, Field(gt=0.0)]
    part: ArticulationName | None = None
    behind: list[ArticulationName] = Field(default_factory=list)
    clearance_m: PositiveFloat | None = Field(
        default=None, description="Free height above the surface inside the asset, metres."
    )


class Articulation(FrozenModel):
    """The moving parts of an asset and the surfaces inside it. The asset's own ``visual``,
    ``collision`` and ``surfaces`` are its carcass (the part that does not move)."""

    parts: list[ArticulatedPart] = Field(min_length=1)
    interior: list[InteriorSurface] = Field(default_factory=list)

    @model_validator(mode="after")
    def _tree(self) -> Articulation:
        seen: set[str] = set()
        joints: set[str] = set()
        for part in self.parts:
            if part.name in seen:
                raise ValueError(f"two parts are named {part.name!r}")
            if part.joint.name in joints:
                raise ValueError(f"two joints are named {part.joint.name!r}")
            if part.parent is not None and part.parent not in seen:
                raise ValueError(f"part {part.name!r}: parent {part.parent!r} must come before it")
            seen.add(part.name)
            joints.add(part.joint.name)
        for surface in self.interior:
            if surface.part is not None and surface.part not in seen:
                raise ValueError(f"interior surface on unknown part {surface.part!r}")
            unknown = [j for j in surface.behind if j not in joints]
            if unknown:
                raise ValueError(f"interior surface behind unknown joints {unknown}")
        return self

    def part(self, name: str) -> ArticulatedPart:
        """The part called ``name`` (KeyError if none)."""
        for part in self.parts:
            if part.name == name:
                return part
        raise KeyError(name)

    @property
    def mass_kg(self) -> float:
        """Total mass of the moving parts."""
        return sum(p.mass_kg for p in self.parts)


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
    placement: list[Placement] = Field(default_factory=lambda: list[Placement](["floor"]))
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
    articulation: Articulation | None = Field(
        default=None,
        description="Moving parts (doors, drawers, lids) with their joints and handles, and "
        "the surfaces inside; None for a rigid asset. When given, ``visual``, ``collision`` "
        "and ``surfaces`` are the carcass's and ``mass_kg`` is the whole asset's.",
    )

    @model_validator(mode="after")
    def _articulated_mass(self) -> AssetMeta:
        moving = self.articulation.mass_kg if self.articulation is not None else 0.0
        if self.articulation is not None and self.mass_kg is None:
            raise ValueError("an articulated asset needs mass_kg (the whole asset's mass)")
        if self.mass_kg is not None and moving >= self.mass_kg:
            raise ValueError(
                f"the moving parts weigh {moving:g} kg, not less than the asset's mass_kg "
                f"{self.mass_kg:g}"
            )
        return self

    @model_serializer(mode="wrap")
    def _without_absent_articulation(self, handler: Any) -> dict[str, Any]:
        # A rigid asset's asset.json stays exactly as before articulation existed.
        data = handler(self)
        if isinstance(data, dict) and data.get("articulation", 0) is None:
            del data["articulation"]
        return data

    @property
    def articulated(self) -> bool:
        """True when the asset has moving parts."""
        return self.articulation is not None

    def files(self) -> list[str]:
        """Every file the metadata names (meshes, textures, thumbnails), in a fixed order."""
        named = [p.mesh for p in self.visual] + [p.texture for p in self.visual if p.texture]
        named += [c.mesh for c in self.collision if c.mesh] + list(self.thumbnails)
        for part in self.articulation.parts if self.articulation is not None else ():
            named += [p.mesh for p in part.visual] + [p.texture for p in part.visual if p.texture]
            named += [c.mesh for c in part.collision if c.mesh]
        return list(dict.fromkeys(named))

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
