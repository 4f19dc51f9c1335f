"""A folder of colour textures imported as user materials: names, descriptions and surfaces
from the file names' words, JPGs as PNGs, large images downscaled, the folder replaced
atomically (:func:`import_textures`)."""

from __future__ import annotations

import io
import json
import re
import shutil
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from holomj.atomic import replace_folder
from holomj.errors import InputError
from holomj.file_names import MATERIALS_INDEX
from holomj.retrieval.materials import (
    SURFACES,
    MaterialEntry,
    MaterialIndex,
    MaterialLibrary,
    Surface,
    UserMaterial,
    default_materials_root,
    read_index,
)
from holomj.spec.materials import BUILTIN_MATERIALS, Material

MAX_TEXTURE_PX = 1024
IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg")


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
