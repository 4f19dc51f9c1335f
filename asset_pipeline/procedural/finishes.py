"""Materials finished as asked: a material's family, the style bias, the finished material and
the main material of a design (the one an object's own colour or material goes to)."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import replace

import numpy as np

from asset_pipeline.procedural.attribute_words import (
    MATERIALS,
    SECONDARY,
    STYLE_BIAS,
    colour_rgb,
)
from asset_pipeline.procedural.attributes import Attributes
from asset_pipeline.procedural.parts import Mesh, Part, RecipeMaterial
from asset_pipeline.procedural.roles import with_material


def family_of(material: RecipeMaterial) -> str:
    """The family of an existing palette material, from its name."""
    name = material.name
    for word, family in (
        ("leather", "leather"),
        ("fabric", "fabric"),
        ("linen", "fabric"),
        ("lacquer", "painted"),
        ("laminate", "painted"),
        ("painted", "painted"),
        ("chair", "painted"),
        ("metal", "metal"),
        ("steel", "metal"),
        ("chrome", "metal"),
        ("brass", "metal"),
        ("gilt", "metal"),
        ("aluminium", "metal"),
        ("glass", "glass"),
        ("plastic", "plastic"),
        ("ceramic", "ceramic"),
        ("porcelain", "ceramic"),
        ("terracotta", "ceramic"),
        ("concrete", "stone"),
    ):
        if word in name:
            return family
    if name in ("oak", "walnut", "pine", "ash", "bark"):
        return "wood"
    return "other"


def styled(attributes: Attributes, base: RecipeMaterial) -> Attributes:
    """``attributes`` with the style's bias filled in when no colour or material is asked."""
    if attributes.style is None or attributes.colour or attributes.material:
        return attributes
    family = family_of(base)
    bias = STYLE_BIAS[attributes.style].get(
        "wood" if family == "painted" else ("fabric" if family == "leather" else family)
    )
    if bias is None:
        return attributes
    material, colour = bias
    return replace(attributes, material=material, colour=colour)


def finished(base: RecipeMaterial, attributes: Attributes) -> RecipeMaterial:
    """The material replacing ``base`` under ``attributes`` (colour and/or material)."""
    rgba, specular, shininess = base.rgba, base.specular, base.shininess
    label_parts = []
    if attributes.material is not None:
        finish = MATERIALS[attributes.material]
        rgba, specular, shininess = finish.rgba, finish.specular, finish.shininess
    if attributes.colour is not None:
        rgb = colour_rgb(attributes.colour)
        assert rgb is not None  # checked by Attributes
        rgba = (*rgb, rgba[3])
        label_parts.append(attributes.colour)
    if attributes.material is not None:
        label_parts.append(MATERIALS[attributes.material].label)
    elif "leather" in base.name:
        label_parts.append("leather")
    slug = re.sub(r"[^a-z0-9]+", "_", " ".join(label_parts)).strip("_")
    return RecipeMaterial(
        f"{base.name}__{slug}",
        _rounded_rgba(rgba),
        specular,
        shininess,
        " ".join(label_parts),
    )


def _mesh_area(mesh: Mesh) -> float:
    tri = mesh.vertices[mesh.faces]
    cross = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    return float(0.5 * np.linalg.norm(cross, axis=1).sum())


def main_material(parts: tuple[Part, ...] | list[Part]) -> RecipeMaterial:
    """The material of the largest visual surface area (secondary materials only if alone)."""
    area: dict[str, float] = {}
    by_name: dict[str, RecipeMaterial] = {}
    for part in parts:
        mesh = part.mesh()
        if mesh is None:
            continue
        by_name[part.material.name] = part.material
        area[part.material.name] = area.get(part.material.name, 0.0) + _mesh_area(mesh)
    names = [n for n in area if n not in SECONDARY] or list(area)
    best = max(sorted(names), key=lambda n: area[n])
    return by_name[best]


def recoloured(
    parts: tuple[Part, ...], base: RecipeMaterial, material: RecipeMaterial
) -> tuple[Part, ...]:
    """``parts`` with every part of material ``base`` made of ``material``."""
    return tuple(with_material(p, material) if p.material.name == base.name else p for p in parts)


def _rounded_rgba(rgba: Iterable[float]) -> tuple[float, float, float, float]:
    r, g, b, a = (round(float(v), 4) for v in rgba)
    return (r, g, b, a)
