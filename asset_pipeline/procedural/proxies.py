"""Honest proxies: a stand-in for a category that neither the library nor a generator supplies.

A proxy is built from a parametric family chosen by the object's placement, its size and the
words of its category (:func:`proxy_family`):

=================  ===========================================================================
family             when
=================  ===========================================================================
frame              on a wall and thin (a board, a sign, a screen): a panel in a frame
slab               flat and wide (height under a fifth of the smaller side; a mat)
slab_on_legs       a table-like word (table, desk, bench, counter, stand...): a top on 4 legs
tapered_column     tall and thin (height over 2.5 x the larger side): a plinth and a tapering
                   shaft
sphere             a ball-like word (ball, globe, orb) with all three extents alike
cylinder           a round word (barrel, drum, bin, bucket, pot, lamp...) on a near-square
                   footprint, or hung from the ceiling on one
rounded_box        a soft word (bag, cushion, pouf, toy, pet...) or a small object
stacked            a large floor object at least 0.8 m tall (a machine, a cabinet): a base and
                   a narrower upper block at the back (-X)
box                anything else
=================  ===========================================================================

It is sized to the plan's size (a cylinder's and a sphere's footprint is square: the smaller
side), labelled with the requested category, described ``"a proxy for a <category>
(<family>)"``, flagged ``proxy: true`` in its metadata, and valid like any procedural asset:
colliders inside the visual, support surfaces with free space above them, and a mass from a
density per placement (:data:`DENSITY`) bounded to a plausible range (:data:`MASS_RANGE`).
"""

from __future__ import annotations

import re
from dataclasses import replace

from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural.assembly import AssetDesign, assemble
from asset_pipeline.procedural.attributes import Attributes
from asset_pipeline.procedural.finishes import finished, styled
from asset_pipeline.procedural.kit import block, square_legs
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.round_parts import Cylinder, Sphere

FAMILIES = (
    "box",
    "rounded_box",
    "cylinder",
    "tapered_column",
    "frame",
    "slab",
    "slab_on_legs",
    "sphere",
    "stacked",
)
PROXY = RecipeMaterial("proxy", (0.60, 0.64, 0.70, 1.0), 0.2, 0.2, "grey-blue")
PROXY_TRIM = RecipeMaterial("proxy_trim", (0.30, 0.32, 0.36, 1.0), 0.3, 0.3, "dark grey")
# kg/m^3 of collider volume: per placement (hollow machines and cabinets are mostly air), and
# per family for the solid ones (a bench top, a column, a panel).
DENSITY = {"floor": 60.0, "wall": 300.0, "ceiling": 100.0, "object": 400.0}
FAMILY_DENSITY = {"slab_on_legs": 350.0, "slab": 250.0, "tapered_column": 250.0, "frame": 300.0}
MASS_RANGE = {
    "floor": (1.0, 150.0),
    "wall": (0.3, 25.0),
    "ceiling": (0.3, 20.0),
    "object": (0.05, 8.0),
}
MIN_EXTENT, MAX_EXTENT = 0.02, 6.0

TABLE_WORDS = frozenset(
    {"table", "desk", "bench", "counter", "workbench", "stand", "station", "trestle", "altar",
     "podium", "lectern", "bar", "island"}
)  # fmt: skip
ROUND_WORDS = frozenset(
    {"barrel", "drum", "bin", "bucket", "can", "pot", "vase", "lamp", "kettlebell", "cylinder",
     "pillar", "pipe", "tank", "jar", "urn", "keg", "planter", "basket", "stool", "candle",
     "bottle", "tube", "roll", "light", "pendant", "chandelier", "lantern", "gong"}
)  # fmt: skip
SPHERE_WORDS = frozenset({"ball", "globe", "sphere", "orb", "balloon"})
SOFT_WORDS = frozenset(
    {"bag", "cushion", "pouf", "pillow", "toy", "pet", "beanbag", "mattress", "plush", "doll",
     "backpack", "towel", "blanket"}
)  # fmt: skip
FLAT_WORDS = frozenset({"rug", "mat", "carpet", "tray", "board", "platform", "pad"})


def category_words(category: str) -> set[str]:
    """The words of a category name (``weight_bench`` -> {weight, bench})."""
    return set(re.findall(r"[a-z]+", category.lower().replace("_", " ")))


def proxy_family(category: str, size: Vec3, placement: str = "floor") -> str:
    """The family a proxy of ``category`` at ``size`` (x = depth, y = width, z = height) gets."""
    x, y, z = size
    words = category_words(category)
    small, large = min(x, y), max(x, y)
    squareish = small / large >= 0.75
    if placement == "wall":
        return "frame" if x <= 0.25 * min(y, z) and min(y, z) >= 0.1 else "box"
    if placement == "ceiling":
        return "cylinder" if squareish else "box"
    if words & SPHERE_WORDS and min(x, y, z) / max(x, y, z) >= 0.75:
        return "sphere"
    if z <= 0.2 * small and (words & FLAT_WORDS or small >= 0.3):
        return "slab"
    if z >= 2.5 * large and large >= 0.08:
        return "tapered_column"
    if words & TABLE_WORDS and z >= 0.3 and small >= 0.25:
        return "slab_on_legs"
    if words & ROUND_WORDS and squareish:
        return "cylinder"
    if words & SOFT_WORDS or placement == "object":
        return "rounded_box" if small >= 0.06 else "box"
    if placement == "floor" and z >= 0.8 and large >= 0.4:
        return "stacked"
    return "box"


def proxy_size(family: str, size: Vec3) -> Vec3:
    """The size a family fills: the requested one, but square footprints for cylinders and
    spheres (the smaller side) and a sphere as tall as wide."""
    x, y, z = (min(max(float(v), MIN_EXTENT), MAX_EXTENT) for v in size)
    if family == "cylinder":
        side = min(x, y)
        return (side, side, z)
    if family == "sphere":
        side = min(x, y, z)
        return (side, side, side * SPHERE_HEIGHT)
    return (x, y, z)


SPHERE_HEIGHT = 1.0 - 0.5 * 0.15  # a sphere is cut flat 15 % of its radius up, to stand still


def _parts(family: str, size: Vec3, main: RecipeMaterial, trim: RecipeMaterial) -> list[Part]:
    x, y, z = size
    hx, hy = 0.5 * x, 0.5 * y
    top = min(x, y) > 0.1  # room for an eroded support surface
    if family == "slab" or family == "box":
        return [block((-hx, hx), (-hy, hy), (0.0, z), main, surface=top)]
    if family == "slab_on_legs":
        t = min(0.05, 0.15 * z)
        side = min(0.06, 0.15 * min(x, y))
        parts: list[Part] = list(square_legs(x, y, z - t, side, trim, inset=0.02 * min(x, y)))
        parts.append(block((-hx, hx), (-hy, hy), (z - t, z), main, surface=top))
        return parts
    if family == "rounded_box":
        r = min(0.15 * min(x, y), 0.08)
        parts = [
            block((-hx + r, hx - r), (-hy, hy), (0.0, z), main, surface=top and x - 2 * r > 0.08),
            block((-hx, hx), (-hy + r, hy - r), (0.0, z), main),
        ]
        for sx in (-1.0, 1.0):
            for sy in (-1.0, 1.0):
                parts.append(Cylinder((sx * (hx - r), sy * (hy - r), 0.5 * z), r, 0.5 * z, main))
        return parts
    if family == "cylinder":
        return [Cylinder((0.0, 0.0, 0.5 * z), hx, 0.5 * z, main, surface=x > 0.12)]
    if family == "sphere":
        r = 0.5 * x
        return [Sphere((0.0, 0.0, r), r, main, cut=0.15 * r)]
    if family == "tapered_column":
        base = 0.08 * z
        parts = [block((-hx, hx), (-hy, hy), (0.0, base), trim)]
        tiers = ((0.8, base, 0.45 * z), (0.65, 0.45 * z, 0.8 * z), (0.5, 0.8 * z, z))
        for k, z0, z1 in tiers:
            parts.append(block((-k * hx, k * hx), (-k * hy, k * hy), (z0, z1), main))
        return parts
    if family == "frame":
        bar = min(0.06, 0.12 * min(y, z))
        parts = [block((-hx, hx - 0.3 * x), (-hy + bar, hy - bar), (bar, z - bar), main)]
        parts += [
            block((-hx, hx), (-hy, hy), (0.0, bar), trim),
            block((-hx, hx), (-hy, hy), (z - bar, z), trim),
            block((-hx, hx), (-hy, -hy + bar), (bar, z - bar), trim),
            block((-hx, hx), (hy - bar, hy), (bar, z - bar), trim),
        ]
        return parts
    if family == "stacked":
        base = 0.35 * z
        back = -hx + 0.4 * x
        front_free = hx - back > 0.1 + 0.04
        parts = [
            block(
                (-hx, hx),
                (-hy, hy),
                (0.0, base),
                trim,
                surface=(back, hx, -hy, hy) if front_free and y > 0.1 else False,
            ),
            block((-hx, back), (-0.8 * hy, 0.8 * hy), (base, z), main, surface=y > 0.15),
        ]
        return parts
    raise ValueError(f"unknown proxy family {family!r}; known: {', '.join(FAMILIES)}")


def build_proxy(
    category: str,
    asset_id: str,
    size: Vec3,
    placement: str = "floor",
    attributes: Attributes | None = None,
    family: str | None = None,
) -> tuple[AssetBundle, str]:
    """The proxy asset of ``category`` at ``size`` (x = depth, y = width, z = height) and its
    family. ``attributes`` colour its main material (see :mod:`.attributes`)."""
    family = family or proxy_family(category, size, placement)
    resolved = proxy_size(family, size)
    attributes = attributes or Attributes()
    main, honoured = PROXY, {}
    wanted = styled(replace(attributes, shape=None), PROXY)
    if wanted.colour or wanted.material:
        main = finished(PROXY, wanted)
        honoured = {
            k: v for k, v in attributes.to_dict().items() if k != "shape" and "." not in k
        }  # a proxy has no parts: "brass handles" are not honoured
    parts = _parts(family, resolved, main, PROXY_TRIM)
    volume = sum(c.volume for p in parts for c in p.colliders())
    low, high = MASS_RANGE.get(placement, MASS_RANGE["floor"])
    density = FAMILY_DENSITY.get(family, DENSITY.get(placement, DENSITY["floor"]))
    mass = min(max(density * volume, low), high)
    noun = category.replace("_", " ")
    words = f"{main.words} " if honoured else ""
    article = "an" if (words or noun)[:1] in "aeiou" else "a"
    design = AssetDesign(
        id=asset_id,
        category=category,
        description=f"a proxy for {article} {words}{noun} ({family.replace('_', ' ')})",
        mass_kg=float(f"{mass:.4g}"),
        friction=0.8,
        placement=(placement,),
        parts=tuple(parts),
        attributes=tuple(honoured.items()),
        proxy=True,
    )
    bundle = assemble(design, expected_size=_expected(family, resolved))
    return bundle, family


def _expected(family: str, size: Vec3) -> Vec3 | None:
    if family == "sphere":
        return None  # the flat cut makes its height a polygonal approximation
    return size


def mass_bounds(placement: str) -> tuple[float, float]:
    """The (min, max) mass in kg a proxy of ``placement`` may get."""
    return MASS_RANGE.get(placement, MASS_RANGE["floor"])


__all__ = ["FAMILIES", "build_proxy", "mass_bounds", "proxy_family", "proxy_size"]
