"""The materials jobs (``holomj materials import|list``): textures in as surface materials, and
what the material library holds (the built-in colours and the user's textures)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from holomj.retrieval.texture_import import TextureImport


@dataclass(frozen=True)
class MaterialListing:
    """The materials of a library: the user folder (None: none) and one row per material."""

    root: Path | None
    rows: list[dict[str, Any]]


def import_materials(
    folder: Path,
    *,
    root: Path | None = None,
    surface: str | None = None,
    texture_size_m: float = 1.0,
) -> TextureImport:
    """Add every colour texture of ``folder`` to the user materials at ``root`` (default
    ``$HOLOMJ_HOME/materials``); see :func:`holomj.retrieval.texture_import.import_textures`."""
    from holomj.retrieval.texture_import import import_textures

    return import_textures(folder, root=root, surface=surface, texture_size_m=texture_size_m)


def list_materials(root: Path | None = None) -> MaterialListing:
    """The built-in materials and those of the user folder ``root`` (default
    ``$HOLOMJ_HOME/materials``): name, built-in or not, surfaces, description, colour, texture."""
    from holomj.retrieval.materials import MaterialLibrary

    library = MaterialLibrary.load(root)
    rows = [
        {
            "name": e.name,
            "builtin": e.builtin,
            "surfaces": list(e.surfaces),
            "description": e.description,
            "rgba": list(e.material.rgba),
            "texture": e.material.texture,
        }
        for e in library.entries
    ]
    return MaterialListing(library.root, rows)
