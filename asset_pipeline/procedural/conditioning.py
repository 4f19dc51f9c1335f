"""Designs built to the attributes asked of them (:mod:`.attributes`).

:func:`asset_design` builds a category's design with them (:func:`condition` the parts):

- **shape** (``round``/``oval``/``square``) for coffee, side and dining tables, (round,
  square) for stools, (round) for mirrors and (``l-shaped``) for desks. Round and square
  tables and stools are the category's own generator at a square footprint (the side is the
  smaller of the planned two), re-drawn until it yields that shape; oval tables, round mirrors
  and L-shaped desks have their own builders (:mod:`.shaped`).
- **parts**: generators tag their parts with roles (:mod:`.roles`); a part request recolours
  only the parts of that role (a seat also its cushion; a table without legs, its base:
  :data:`~.attribute_words.PART_TARGETS`), with one new material per material replaced, so
  the asset's visual meshes show it. The design is re-drawn (up to :data:`PART_DRAWS` times)
  until it has the part (a sofa on legs rather than a plinth); a part the design lacks is
  reported, not faked
  (:func:`condition` gives per part how it was honoured or why not).
- **colour / material** go to the design's MAIN material: the material with the largest visual
  surface area, bedding, screens, mirror glass, soil and foliage left out (so a bed's frame, a
  mirror's frame, a plant's pot), parts that a part request names left out too ("a wooden
  table with a glass top": the legs are the wood); every part of that material changes with
  it. A colour alone
  keeps the finish (specular, shininess) of the material it replaces; a material alone brings
  its own colour.
- **style** biases the main material when no colour or material is asked (rustic -> pine,
  victorian -> burgundy velvet upholstery, industrial -> black metal, ...), so a style still
  shows; it is recorded as honoured then.

Everything is deterministic: the same inputs give the same design.
"""

from __future__ import annotations

import re
import zlib
from dataclasses import dataclass, replace

import numpy as np

from asset_pipeline.procedural.assembly import AssetDesign
from asset_pipeline.procedural.attribute_words import (
    MATERIALS,
    PART_NOUNS,
    PART_ROLES,
    PLURAL_ROLES,
    part_targets,
)
from asset_pipeline.procedural.attributes import Attributes, PartAttributes
from asset_pipeline.procedural.finishes import finished, main_material, recoloured, styled
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import CategoryInfo, Design, rng_for
from asset_pipeline.procedural.roles import ROLES, role_of, with_material
from asset_pipeline.procedural.shaped import (
    SHAPED,
    shape_builder,
    shaped_size,
)


@dataclass(frozen=True)
class Conditioned:
    """A design built to a request: the design, the size it fills, the attributes honoured
    (as :meth:`Attributes.to_dict` keys) and, per part asked, how it was honoured or why not."""

    design: Design
    size: Vec3
    honoured: dict[str, str]
    parts_report: dict[str, str]


PART_DRAWS = 16
"""Designs drawn at most to find one with every part asked (a sofa on legs, not on a plinth)."""


def condition(info: CategoryInfo, size: Vec3, seed: int, attributes: Attributes) -> Conditioned:
    """The design of ``info`` at ``size`` honouring ``attributes``.

    A shape the category cannot take is left out of the honoured attributes. Part requests
    (``"brass handles"``) recolour the parts carrying that role (:mod:`.roles`) only: the
    design is re-drawn (up to :data:`PART_DRAWS` times) until it has such parts; without them
    the request goes to the roles standing in for them (:data:`PART_TARGETS`: a table's base
    for its legs), else it is reported as not honoured. The object's own colour or material
    goes to the main material of the parts no request names.
    """
    honoured: dict[str, str] = {}
    name = info.name
    shape = attributes.shape if attributes.shape in SHAPED.get(name, ()) else None
    size = info.check_size(shaped_size(info, shape, size))
    rng = rng_for(name, seed)
    own = shape_builder(name, shape) if shape is not None else None
    if own is not None:
        shaped_parts, shaped_words = own(size, rng)
        design = Design(tuple(shaped_parts), shaped_words)
    elif shape is not None or attributes.parts:
        design = _drawn(info, size, seed, rng, shape, attributes.parts)
    else:
        design = info.builder(size, rng)
    if shape is not None:
        honoured["shape"] = shape
    targets = {p.role: _targets(design.parts, p.role) for p in attributes.parts}
    named = {k for indices, _ in targets.values() for k in indices}
    rest = [p for k, p in enumerate(design.parts) if k not in named]
    base = main_material(rest or design.parts)
    wanted = styled(attributes, base)
    words = dict(design.words)
    parts = design.parts
    if wanted.colour is not None or wanted.material is not None:
        material = finished(base, wanted)
        parts = recoloured(parts, base, material)
        _reworded(words, base.words, material.words)
        for key in ("colour", "material"):
            if getattr(attributes, key) is not None:
                honoured[key] = getattr(attributes, key)
    if attributes.style is not None and (
        wanted is not attributes or attributes.colour or attributes.material
    ):
        honoured["style"] = attributes.style
    report: dict[str, str] = {}
    for request in attributes.parts:
        indices, stand_in = targets[request.role]
        if not indices:
            noun = request.role.replace("_", " ")
            report[request.role] = f"not honoured: this {name.replace('_', ' ')} has no {noun}"
            continue
        parts = _finished_parts(parts, indices, request, words)
        for key in ("colour", "material"):
            if getattr(request, key) is not None:
                honoured[f"{request.role}.{key}"] = getattr(request, key)
        look = " ".join(w for w in (request.colour, _label(request.material)) if w)
        roles = sorted({role_of(parts[k]) or "" for k in indices}, key=ROLES.index)
        where = " and ".join(roles)
        text = f"{look} on the {where} ({len(indices)} part{'s' if len(indices) > 1 else ''})"
        if stand_in:
            text += f": this {name.replace('_', ' ')} has no {request.role}"
        report[request.role] = text
    return Conditioned(
        Design(tuple(parts), words), size, dict(sorted(honoured.items(), key=_order)), report
    )


def parts_report(
    info: CategoryInfo, size: Vec3 | None, seed: int, attributes: Attributes
) -> dict[str, str]:
    """How each part request of ``attributes`` is honoured by the asset of ``info`` (a rigid or
    an articulated category) at ``size`` in style ``seed`` (the design only, nothing
    assembled): role -> ``"brass on the handles (8 parts)"`` or ``"not honoured: ..."``."""
    if not attributes.parts:
        return {}
    return condition(info, info.check_size(size), seed, attributes).parts_report


def asset_design(
    info: CategoryInfo,
    asset_id: str,
    size: Vec3 | None = None,
    seed: int = 0,
    attributes: Attributes | None = None,
) -> tuple[AssetDesign, Vec3]:
    """The design of asset ``asset_id`` of ``info`` (not yet assembled) and the size it fills.

    With ``attributes`` the design honours the colour, material, shape, style and parts asked
    where it can (:func:`condition`); the honoured ones are recorded in the design and its
    description says so. Without them the design is exactly the category generator's.
    """
    resolved = info.check_size(size)
    honoured: dict[str, str] = {}
    if attributes:
        made = condition(info, resolved, seed, attributes)
        design, resolved, honoured = made.design, made.size, made.honoured
    else:
        design = info.builder(resolved, rng_for(info.name, seed))
    description = " ".join(info.description.format(**design.words).split())
    if attributes:
        description = described(description, info.name, attributes, honoured)
    asset = AssetDesign(
        id=asset_id,
        category=info.name,
        description=description,
        mass_kg=info.mass_for(resolved),
        friction=info.friction,
        placement=info.placement,
        parts=design.parts,
        attributes=tuple(honoured.items()),
    )
    return asset, resolved


def _drawn(
    info: CategoryInfo,
    size: Vec3,
    seed: int,
    rng: np.random.Generator,
    shape: str | None,
    asked: tuple[PartAttributes, ...],
) -> Design:
    """The category's design, re-drawn until it has ``shape`` (up to 32 draws) and, within
    :data:`PART_DRAWS` draws, parts for every request of ``asked`` (else the first draw of the
    shape)."""
    first = None
    draws = 32 if shape is not None else PART_DRAWS
    for k in range(draws):
        attempt = (
            rng
            if k == 0
            else np.random.default_rng([int(seed), zlib.crc32(info.name.encode()), 1000 + k])
        )
        candidate = info.builder(size, attempt)
        if shape is not None and candidate.words.get("shape") != shape:
            continue
        if first is None:
            first = candidate
        if all(_targets(candidate.parts, p.role)[0] and not _targets(candidate.parts, p.role)[1]
               for p in asked):  # fmt: skip
            return candidate
        if k >= PART_DRAWS - 1 or not any(role_of(p) for p in candidate.parts):
            break  # an untagged generator: no draw will have the parts
    if first is None:  # pragma: no cover - 32 draws at 60 % each
        raise ValueError(f"no {shape} {info.name} in {draws} draws")
    return first


def _targets(parts: tuple[Part, ...], role: str) -> tuple[list[int], bool]:
    """Indices of the parts a request for ``role`` recolours, and whether they stand in for
    parts the design lacks (a table's base for its legs)."""
    primary, instead = part_targets(role)
    found = [k for k, p in enumerate(parts) if role_of(p) in primary]
    if found:
        return found, False
    return [k for k, p in enumerate(parts) if role_of(p) in instead], True


def _finished_parts(
    parts: tuple[Part, ...], indices: list[int], request: PartAttributes, words: dict[str, str]
) -> tuple[Part, ...]:
    """``parts`` with those at ``indices`` finished as ``request`` asks (one new material per
    material replaced), the design's words following."""
    made: dict[str, RecipeMaterial] = {}
    out = list(parts)
    for k in indices:
        base = parts[k].material
        if base.name not in made:
            new = finished(base, request.finish())
            slug = new.name.removeprefix(f"{base.name}__")
            made[base.name] = replace(new, name=f"{base.name}__{request.role}_{slug}")
            for key in _word_keys(request.role):
                if words.get(key):
                    words[key] = _renamed(words[key], base.words, made[base.name].words)
                    break
        out[k] = with_material(parts[k], made[base.name])
    return tuple(out)


def _word_keys(role: str) -> tuple[str, ...]:
    """The keys of a design's words that may name the material of ``role`` parts."""
    return {
        "handles": ("handle", "handles"),
        "seat": ("cushion",),
        "cushions": ("cushion",),
        "legs": ("legs", "leg"),
        "base": ("legs", "base"),
        "top": ("top",),
        "shade": ("shade",),
        "frame": ("frame",),
        "headboard": ("headboard",),
        "pole": ("metal",),
    }.get(role, (role,))


def _renamed(text: str, old: str, new: str) -> str:
    """``text`` naming ``new`` where it named ``old`` (or, when it did not, ``new`` put in
    front: ``"square legs"`` -> ``"black metal square legs"``, ``"a pedestal"`` -> ``"a black
    metal pedestal"``)."""
    if old and old in text:
        return text.replace(old, new)
    if new in text or text != text.strip() or text.startswith(("and ", "with ", "on ")):
        return text  # not a noun phrase (" and a grey seat cushion")
    head, _, rest = text.partition(" ")
    if head in ("a", "an") and rest:
        return f"{_article(new)} {new} {rest}"
    return f"{new} {text}"


def _reworded(words: dict[str, str], old: str, new: str) -> None:
    for key, value in words.items():
        if old and old in value:
            words[key] = value.replace(old, new)


def _label(material: str | None) -> str | None:
    return MATERIALS[material].label if material else None


def _order(item: tuple[str, str]) -> tuple[int, int, int]:
    role, dot, kind = item[0].partition(".")
    if not dot:
        return (0, ("colour", "material", "shape", "style").index(role), 0)
    return (1, PART_ROLES.index(role), ("colour", "material").index(kind))


def described(
    description: str, category: str, attributes: Attributes, honoured: dict[str, str]
) -> str:
    """``description`` saying what was honoured: the words asked, where the text lacks them
    (the object's in front, its parts' after it: ``"... with brass handles"``)."""
    text = " ".join(description.split())
    shown = Attributes.from_dict(honoured)
    wanted = [w for w in (shown.colour, MATERIALS[shown.material].label if shown.material else None)
              if w]  # fmt: skip
    missing = [w for w in wanted if w not in text]
    if shown.shape and shown.shape not in text:
        missing.append(shown.shape)
    if missing:
        head, _, rest = text.partition(" ")
        if head.lower() in ("a", "an") and rest:
            text = f"a {' '.join(missing)} {rest}"
        else:
            noun = category.replace("_", " ")
            text = f"a {' '.join(missing)} {noun}: {text}"
    if shown.style and shown.style not in text:
        words = text.split(" ", 1)
        if len(words) == 2 and words[0].lower() in ("a", "an"):
            text = f"{_article(shown.style)} {shown.style} {words[1]}"
        else:
            text = f"{shown.style} {text}"
    words = text.split(" ", 2)
    if len(words) >= 2 and words[0] in ("a", "an"):
        words[0] = _article(words[1])
        text = " ".join(words)
    for part in shown.parts:
        look = part.words().rsplit(" ", 1)[0]
        primary, instead = part_targets(part.role)
        roles = {part.role, *primary, *instead}
        nouns = "|".join(re.escape(n) for n, role in PART_NOUNS.items() if role in roles)
        if re.search(rf"\b{re.escape(look)}(?: [a-z-]+){{0,2}} (?:{nouns})\b", text):
            continue  # "white conical shade", "metal square legs", "black metal pedestal"
        phrase = part.words() if part.role in PLURAL_ROLES else f"{_article(look)} {part.words()}"
        text += f" and {phrase}" if " with " in text else f" with {phrase}"
    return text


def _article(word: str) -> str:
    return "an" if word[:1].lower() in "aeiou" else "a"
