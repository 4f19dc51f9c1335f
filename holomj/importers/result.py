"""What an importer returns: the scene plus a record of every liberty it took."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any

from holomj.spec.scene import SceneSpec


@dataclass(frozen=True)
class Substitution:
    """An object whose requested asset was replaced by another one from the library.

    ``reason`` says why, e.g. ``"not in library; same category, closest size"`` or
    ``"no asset of category 'x'; box of the object's size"``.
    """

    object_id: str
    requested_asset: str
    category: str
    used_asset: str
    reason: str


@dataclass(frozen=True)
class ImportResult:
    """A scene read from an input file, with the substitutions and warnings of the import."""

    scene: SceneSpec
    format: str
    substitutions: list[Substitution] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)

    def to_report(self) -> dict[str, Any]:
        """A JSON-able summary: format, counts, substitutions and warnings."""
        scene = self.scene
        return {
            "format": self.format,
            "source": scene.source,
            "rooms": len(scene.rooms),
            "doors": len(scene.doors),
            "windows": len(scene.windows),
            "objects": len(scene.objects),
            "lights": len(scene.lights),
            "substitutions": [asdict(s) for s in self.substitutions],
            "warnings": list(self.warnings),
        }
