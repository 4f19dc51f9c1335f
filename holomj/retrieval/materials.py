"""Materials for room surfaces: a library of built-in colours and user textures, chosen by text.

A material library is the built-in palette (``BUILTIN_MATERIALS``, described in
``holomj/data/material_descriptions.json`` with the surfaces each may cover) plus the textured
materials of a user folder (default ``$HOLOMJ_HOME/materials``, beside the default asset
library)::

    MATERIALS/materials.json     MaterialIndex: {"schema_version", "materials": {name: ...}}
    MATERIALS/<name>.png         the tiling texture of each user material

:func:`choose_material` picks, among the materials allowed on a surface (floor, wall or
ceiling), the one whose name and description are closest to a description in sentence-
embedding space (an exact name wins outright). A textured material's ``Material.texture`` is
the absolute path of its PNG; the exporter copies it into the scene's folder.
:func:`holomj.retrieval.texture_import.import_textures` adds a folder of PNG/JPG textures,
atomically.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import Field

from holomj.errors import InputError, SpecError
from holomj.file_names import MATERIALS_INDEX
from holomj.library.location import holomj_home
from holomj.retrieval.text import TextEncoder
from holomj.spec.base import FrozenModel, Identifier, read_json, validate_model
from holomj.spec.materials import BUILTIN_MATERIALS, Material

MATERIALS_SCHEMA_VERSION: Literal["1.0"] = "1.0"
Surface = Literal["floor", "wall", "ceiling"]
SURFACES: tuple[Surface, ...] = ("floor", "wall", "ceiling")


class UserMaterial(FrozenModel):
    """One entry of a user materials folder (``texture`` relative to the folder)."""

    description: str = Field(min_length=1, max_length=300)
    surfaces: list[Surface] = Field(min_length=1)
    material: Material
    source: str | None = Field(default=None, description="The file it was imported from.")


class MaterialIndex(FrozenModel):
    """``materials.json`` of a user materials folder."""

    schema_version: Literal["1.0"] = MATERIALS_SCHEMA_VERSION
    materials: dict[Identifier, UserMaterial] = Field(default_factory=dict)


@dataclass(frozen=True)
class MaterialEntry:
    """A material as choices see it: name, look, description, allowed surfaces, origin."""

    name: str
    material: Material
    description: str
    surfaces: tuple[str, ...]
    builtin: bool

    @property
    def text(self) -> str:
        """What a description is compared with: ``"oak floor: light oak wood floor boards"``."""
        return f"{self.name.replace('_', ' ')}: {self.description}"


def default_materials_root() -> Path:
    """The user materials folder used unless one is given: ``$HOLOMJ_HOME/materials``."""
    return holomj_home() / "materials"


def builtin_entries() -> list[MaterialEntry]:
    """The built-in palette with descriptions and surfaces (every built-in is described)."""
    path = resources.files("holomj.data").joinpath("material_descriptions.json")
    table = json.loads(path.read_text(encoding="utf-8"))
    entries = []
    for name, material in BUILTIN_MATERIALS.items():
        info = table.get(name)
        if info is None:
            raise SpecError(
                f"built-in material {name!r} has no description", where="material_descriptions.json"
            )
        entries.append(
            MaterialEntry(
                name=name,
                material=material,
                description=info["description"],
                surfaces=tuple(info["surfaces"]),
                builtin=True,
            )
        )
    return entries


@dataclass
class MaterialLibrary:
    """Built-in and user materials, with their text embeddings cached per encoder."""

    entries: list[MaterialEntry]
    root: Path | None = None
    _vectors: dict[str, np.ndarray] = field(default_factory=dict, repr=False)
    _queries: dict[tuple[str, str], np.ndarray] = field(default_factory=dict, repr=False)

    @classmethod
    def load(cls, root: Path | str | None = None) -> MaterialLibrary:
        """The built-ins plus the user folder ``root`` (default :func:`default_materials_root`);
        a folder without ``materials.json`` adds nothing."""
        folder = Path(root) if root is not None else default_materials_root()
        entries = builtin_entries()
        index = read_index(folder)
        for name, item in sorted(index.materials.items()):
            if name in BUILTIN_MATERIALS:
                raise SpecError(
                    f"material {name!r} shadows a built-in one", where=str(folder / MATERIALS_INDEX)
                )
            material = item.material
            if material.texture is not None:
                texture = (folder / material.texture).absolute()
                if not texture.is_file():
                    raise SpecError(
                        f"texture {material.texture!r} of material {name!r} is missing",
                        where=str(folder / MATERIALS_INDEX),
                    )
                material = material.model_copy(update={"texture": str(texture)})
            entries.append(
                MaterialEntry(name, material, item.description, tuple(item.surfaces), False)
            )
        return cls(entries, folder)

    def get(self, name: str) -> MaterialEntry:
        """The material called ``name``."""
        for entry in self.entries:
            if entry.name == name:
                return entry
        raise InputError(f"unknown material {name!r}", fix="see 'holomj materials list'")

    def for_surface(self, surface: str) -> list[MaterialEntry]:
        """The materials allowed on ``surface`` (floor, wall or ceiling)."""
        if surface not in SURFACES:
            raise InputError(
                f"unknown surface {surface!r}", fix=f"use one of: {', '.join(SURFACES)}"
            )
        return [e for e in self.entries if surface in e.surfaces]

    def vectors(self, encoder: TextEncoder) -> np.ndarray:
        """Embeddings of every entry's text, (len(entries), dim), computed once per encoder."""
        if encoder.name not in self._vectors:
            self._vectors[encoder.name] = encoder.encode([e.text for e in self.entries])
        return self._vectors[encoder.name]

    def query(self, encoder: TextEncoder, description: str) -> np.ndarray:
        """The embedding of a description (cached)."""
        key = (encoder.name, description)
        if key not in self._queries:
            self._queries[key] = encoder.encode([description])[0]
        return self._queries[key]


def read_index(folder: Path) -> MaterialIndex:
    """The index of a user materials folder (empty when it has none)."""
    path = Path(folder) / MATERIALS_INDEX
    if not path.is_file():
        return MaterialIndex()
    return validate_model(MaterialIndex, read_json(path), str(path))


def choose_material(
    description: str, surface: str, *, library: MaterialLibrary, encoder: TextEncoder
) -> tuple[str, Material]:
    """The material for ``description`` on ``surface``: its name and look.

    A description that names an allowed material (``"oak_floor"``, ``"oak floor"``) gets it;
    otherwise the allowed material with the highest cosine similarity between the description
    and ``"<name words>: <description>"`` wins, ties going to the first name in sort order.
    """
    allowed = library.for_surface(surface)
    if not allowed:
        raise InputError(f"no material may cover a {surface}", where=description)
    wanted = "_".join(re.findall(r"[a-z0-9]+", description.lower()))
    for entry in allowed:
        if entry.name.lower() == wanted:
            return entry.name, entry.material
    rows = {e.name: k for k, e in enumerate(library.entries)}
    matrix = library.vectors(encoder)[[rows[e.name] for e in allowed]]
    scores = matrix @ library.query(encoder, description)
    best = min(range(len(allowed)), key=lambda k: (-float(scores[k]), allowed[k].name))
    return allowed[best].name, allowed[best].material


def material_picker(
    *, encoder: TextEncoder, materials: Path | None = None
) -> Callable[[str, str], tuple[str, Material]]:
    """``pick(description, surface) -> (name, Material)`` over the library at ``materials``."""
    library = MaterialLibrary.load(materials)

    def pick(description: str, surface: str) -> tuple[str, Material]:
        return choose_material(description, surface, library=library, encoder=encoder)

    return pick


# -- importing textures -------------------------------------------------------------------------
