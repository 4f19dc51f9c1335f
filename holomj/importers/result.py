"""What an importer returns: the scene plus a record of every liberty it took."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any

from holomj.spec.scene import SceneSpec


@dataclass(frozen=True)
class Substitution:
    """An object whose requested asset was replaced by another one from the library.

    ``reason`` says why, e.g. ``"not in library; same category, closest size"`` or
    ``"no asset of category 'x'; box of the object's size"``. ``scale`` is the scale the used
    asset got (one factor, or depth/width/height factors); ``source_size`` the original's size
    (x = depth, y = width, z = height, metres) when the input or a table told it, and
    ``size_source`` where that size came from (``"thor"``: the AI2-THOR asset table,
    ``"footprint"``: the input's own footprint, ``"category"``: a typical size of the category,
    ``"guess"``: the 0.5 m cube). ``turn_deg`` (0 or 90) is how far the used asset is turned
    about Z within the object, its ``scale`` being in the asset's own frame.
    """

    object_id: str
    requested_asset: str
    category: str
    used_asset: str
    reason: str
    scale: float | tuple[float, float, float] = 1.0
    source_size: tuple[float, float, float] | None = None
    size_source: str | None = None
    turn_deg: float = 0.0


@dataclass(frozen=True)
class ImportResult:
    """A scene read from an input file, with the substitutions and warnings of the import, and
    the objects ``merged`` into their parent's stand-in (a THOR sink's faucet: holomj's sinks
    have their own), each ``{object, category, into, why}``."""

    scene: SceneSpec
    format: str
    substitutions: list[Substitution] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    merged: list[dict[str, str]] = field(default_factory=list)

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
            "merged": [dict(m) for m in self.merged],
            "warnings": list(self.warnings),
        }
