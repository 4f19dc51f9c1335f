"""Pure data: scene, assets, materials, walls. Imports nothing of holomj but errors."""

from holomj.spec.assets import AssetMeta, CollisionPart, LibraryIndex, SupportSurface, VisualPart
from holomj.spec.materials import BUILTIN_MATERIALS, Material
from holomj.spec.scene import (
    SCHEMA_VERSION,
    Camera,
    Door,
    Light,
    Room,
    SceneObject,
    SceneSpec,
    Window,
)
from holomj.spec.walls import Wall, derive_walls

__all__ = [
    "BUILTIN_MATERIALS",
    "SCHEMA_VERSION",
    "AssetMeta",
    "Camera",
    "CollisionPart",
    "Door",
    "LibraryIndex",
    "Light",
    "Material",
    "Room",
    "SceneObject",
    "SceneSpec",
    "SupportSurface",
    "VisualPart",
    "Wall",
    "Window",
    "derive_walls",
]
