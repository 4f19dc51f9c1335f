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
:func:`import_textures` adds a folder of PNG/JPG textures, atomically.
"""

from __future__ import annotations

import io
import json
import re
import shutil
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import Field

from holomj.atomic import replace_folder
from holomj.errors import InputError, SpecError
from holomj.file_names import MATERIALS_INDEX
from holomj.library.location import holomj_home
from holomj.retrieval.text import TextEncoder
from holomj.spec.base import FrozenModel, Identifier, read_json, validate_model
from holomj.spec.materials import BUILTIN_MATERIALS, Material

MATERIALS_SCHEMA_VERSION: Literal["1.0"] = "1.0"
MAX_TEXTURE_PX = 1024
IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg")
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

# Leading tokens naming common texture packs, dropped from names ("libero_wood" -> "wood").
SOURCE_PREFIXES = frozenset(
    {"libero", "rs", "ph", "polyhaven", "scenesim", "ambientcg", "cgbookcase", "tex", "texture"}
)
# Tokens of maps that are not colour (normal, roughness, ...): such files are skipped.
MAP_TOKENS = frozenset(
    {
        "nor", "nrm", "normal", "normalgl", "normaldx", "rough", "roughness", "disp",
        "displacement", "ao", "arm", "bump", "height", "spec", "specular", "gloss",
        "glossiness", "metallic", "metalness", "opacity", "mask",
    }
)  # fmt: skip
# Tokens that say nothing about the look (colour-map markers, resolutions).
NOISE_TOKENS = frozenset({"diff", "diffuse", "albedo", "basecolor", "color", "colour", "col"})
FLOOR_WORDS = frozenset(
    {"floor", "floors", "flooring", "floorboard", "floorboards", "plank", "planks", "parquet",
     "carpet", "rug", "felt", "laminate"}
)  # fmt: skip
WALL_WORDS = frozenset(
    {"wall", "walls", "plaster", "stucco", "brick", "bricks", "wallpaper", "paint", "painted",
     "linen", "fabric", "panel", "panels"}
)  # fmt: skip
TILE_WORDS = frozenset({"tile", "tiles", "tiled"})
CEILING_WORDS = frozenset({"ceiling"})


def texture_words(stem: str) -> list[str]:
    """Words of a texture file's stem: ``libero_seamless_wood_planks_floor`` ->
    ``[seamless, wood, planks, floor]`` (pack prefix, resolutions and digits dropped)."""
    tokens = re.findall(r"[a-z0-9]+", stem.lower())
    if len(tokens) > 1 and tokens[0] in SOURCE_PREFIXES:
        tokens = tokens[1:]
    words = []
    for token in tokens:
        if re.fullmatch(r"\d+k|\d+px|\d+", token) or token in NOISE_TOKENS:
            continue
        word = re.sub(r"\d+$", "", token)
        if word:
            words.append(word)
    return words


def is_auxiliary_map(stem: str) -> bool:
    """True for normal, roughness, displacement ... maps (``*_nor_gl_1k``, ``*_rough_*``)."""
    return any(token in MAP_TOKENS for token in re.findall(r"[a-z0-9]+", stem.lower()))


def guess_surfaces(words: Sequence[str]) -> list[Surface]:
    """Surfaces a texture suits, from its words; all three when they say nothing."""
    found = set(words)
    surfaces: set[Surface] = set()
    if found & FLOOR_WORDS:
        surfaces.add("floor")
    if found & WALL_WORDS:
        surfaces.add("wall")
    if found & TILE_WORDS:
        surfaces |= {"floor", "wall"}
    if found & CEILING_WORDS:
        surfaces.add("ceiling")
    return [s for s in SURFACES if s in surfaces] or list(SURFACES)


def _specular(words: Sequence[str]) -> tuple[float, float]:
    found = set(words)
    if found & {"metal", "steel", "chrome", "brushed", "aluminium", "aluminum", "brass"}:
        return 0.7, 0.6
    if found & {"tile", "tiles", "marble", "ceramic", "porcelain", "glazed", "polished"}:
        return 0.4, 0.5
    if found & {"carpet", "felt", "fabric", "linen", "rug", "wool"}:
        return 0.0, 0.1
    if found & {"plaster", "stucco", "paint", "painted", "brick", "bricks", "concrete", "stone"}:
        return 0.05, 0.1
    if found & {"wood", "plank", "planks", "floorboard", "parquet", "veneer", "varnished"}:
        return 0.15, 0.3
    return 0.1, 0.2


@dataclass(frozen=True)
class TextureImport:
    """What :func:`import_textures` did."""

    root: Path
    added: list[MaterialEntry]
    replaced: list[str]
    skipped: list[tuple[str, str]]

    def to_dict(self) -> dict:
        """A JSON-friendly summary."""
        return {
            "materials": str(self.root),
            "added": [
                {
                    "name": e.name,
                    "description": e.description,
                    "surfaces": list(e.surfaces),
                    "texture": e.material.texture,
                }
                for e in self.added
            ],
            "replaced": self.replaced,
            "skipped": [{"file": f, "reason": r} for f, r in self.skipped],
        }


def import_textures(
    folder: Path,
    *,
    root: Path | None = None,
    surface: str | None = None,
    texture_size_m: float = 1.0,
) -> TextureImport:
    """Add every colour texture (PNG/JPG) of ``folder`` to the user materials at ``root``.

    Names and descriptions come from the file stems, surfaces from their words unless
    ``surface`` is given (floor, wall, ceiling or any). JPGs become PNGs; images larger than
    :data:`MAX_TEXTURE_PX` are downscaled. A material of the same name is replaced. Every image
    is read before anything is written, and the folder is replaced atomically, so bad input
    leaves it as it was.
    """
    folder = Path(folder)
    target = Path(root) if root is not None else default_materials_root()
    images, skipped = _texture_images(folder, surface, texture_size_m)
    index = read_index(target)
    prepared = _prepared_materials(images, surface, texture_size_m)
    replaced = sorted(n for n, _, _ in prepared if n in index.materials)
    merged = dict(index.materials)
    merged.update({name: item for name, item, _ in prepared})
    _write_materials(target, prepared, MaterialIndex(materials=dict(sorted(merged.items()))))
    library = MaterialLibrary.load(target)
    added = [library.get(name) for name, _, _ in prepared]
    return TextureImport(target, added, replaced, skipped)


def _texture_images(
    folder: Path, surface: str | None, texture_size_m: float
) -> tuple[list[Path], list[tuple[str, str]]]:
    """The colour textures of ``folder`` and the images skipped (with why); bad options or a
    folder without colour textures are refused."""
    if surface is not None and surface not in (*SURFACES, "any"):
        raise InputError(
            f"unknown surface {surface!r}", where="--surface", fix="use floor, wall, ceiling or any"
        )
    if not texture_size_m > 0 or not np.isfinite(texture_size_m):
        raise InputError(
            f"texture size must be a positive number of metres, got {texture_size_m}",
            where="--texture-size",
        )
    if not folder.is_dir():
        raise InputError("texture folder not found", where=str(folder))
    images = sorted(
        p for p in folder.iterdir() if p.is_file() and p.suffix.lower() in IMAGE_SUFFIXES
    )
    skipped = [(p.name, "not a colour map") for p in images if is_auxiliary_map(p.stem)]
    images = [p for p in images if not is_auxiliary_map(p.stem)]
    if not images:
        raise InputError(
            "no colour texture images (PNG/JPG) in folder",
            where=str(folder),
            fix="point at a folder of .png/.jpg textures",
        )
    return images, skipped


def _prepared_materials(
    images: list[Path], surface: str | None, texture_size_m: float
) -> list[tuple[str, UserMaterial, bytes]]:
    """(name, index entry, PNG bytes) of each texture image, every image read."""
    taken: set[str] = set()
    prepared: list[tuple[str, UserMaterial, bytes]] = []
    for path in images:
        words = texture_words(path.stem) or [re.sub(r"[^a-z0-9]+", "_", path.stem.lower())]
        name = _unique_name("_".join(words), taken)
        taken.add(name)
        surfaces: list[Surface]
        if surface is None:
            surfaces = guess_surfaces(words)
        else:
            surfaces = list(SURFACES) if surface == "any" else [s for s in SURFACES if s == surface]
        specular, shininess = _specular(words)
        item = UserMaterial(
            description=" ".join(words),
            surfaces=surfaces,
            material=Material(
                rgba=(1.0, 1.0, 1.0, 1.0),
                texture=f"{name}.png",
                texture_size_m=texture_size_m,
                specular=specular,
                shininess=shininess,
            ),
            source=path.name,
        )
        prepared.append((name, item, _png_bytes(path)))
    return prepared


def _write_materials(
    target: Path, prepared: list[tuple[str, UserMaterial, bytes]], index: MaterialIndex
) -> None:
    """The materials folder with the new textures and ``index``, replaced atomically."""

    def fill(tmp: Path) -> None:
        if target.is_dir():
            for old in target.iterdir():
                if old.is_file() and old.name != MATERIALS_INDEX:
                    shutil.copy2(old, tmp / old.name)
        for name, _, data in prepared:
            (tmp / f"{name}.png").write_bytes(data)
        text = json.dumps(index.model_dump(mode="json"), indent=2, sort_keys=True) + "\n"
        (tmp / MATERIALS_INDEX).write_text(text, encoding="utf-8")

    try:
        replace_folder(target, fill)
    except OSError as err:
        raise InputError(
            f"cannot write the materials folder: {err.strerror or err}", where=str(target)
        ) from None


def _unique_name(name: str, taken: set[str]) -> str:
    base = name if name not in BUILTIN_MATERIALS else f"{name}_texture"
    candidate, k = base, 2
    while candidate in taken:
        candidate, k = f"{base}_{k}", k + 1
    return candidate


def _png_bytes(path: Path) -> bytes:
    """The image at ``path`` as RGB PNG bytes, at most :data:`MAX_TEXTURE_PX` on a side
    (an RGB PNG small enough is kept byte for byte, after decoding it once as a check)."""
    from PIL import Image, UnidentifiedImageError

    try:
        data = path.read_bytes()
        with Image.open(io.BytesIO(data)) as img:
            img.load()
            as_is = img.format == "PNG" and img.mode == "RGB"
            rgb = img.convert("RGB")
    except (OSError, UnidentifiedImageError, ValueError) as err:
        raise InputError(f"cannot read image: {err}", where=str(path)) from None
    if as_is and max(rgb.size) <= MAX_TEXTURE_PX:
        return data
    if max(rgb.size) > MAX_TEXTURE_PX:
        scale = MAX_TEXTURE_PX / max(rgb.size)
        size = (max(1, round(rgb.width * scale)), max(1, round(rgb.height * scale)))
        rgb = rgb.resize(size, Image.Resampling.LANCZOS)
    buffer = io.BytesIO()
    rgb.save(buffer, format="PNG", compress_level=3)
    return buffer.getvalue()
