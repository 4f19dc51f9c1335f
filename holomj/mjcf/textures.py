"""Procedural surface textures: wood, planks, fabric, velvet, leather, marble, tile, brick,
carpet and concrete, drawn with numpy and encoded as greyscale PNG.

Every pattern is seamless (it tiles in both directions: its noise is filtered white noise in
the Fourier domain, hence periodic, and every stripe or grid has a whole number of periods per
image) and deterministic (a fixed seed per pattern, 8-bit output, a fixed PNG encoding). A
pattern is a luminance map meant to be *tinted*: MuJoCo multiplies a material's ``rgba`` by its
texture, so a material shows its colour modulated by the pattern; :func:`tinted` gives the
``rgba`` whose product with the pattern averages to a colour (asset parts and room surfaces
both use it). The patterns are bright (mean luminance about 0.85, brick aside), so even a light
colour rarely needs more than a channel value of 1 to keep its average.

Each pattern covers :attr:`Pattern.tile_m` metres of surface, so grain, threads, tiles and bricks
have their physical size wherever the texture coordinates are in metres / ``tile_m``.
:func:`pattern_for_name` picks a pattern from a material's name or description words
(``"light oak wood floor"`` -> planks, ``"grey carpet"`` -> carpet).
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from holomj.mjcf.png import png_bytes
from holomj.spec.materials import Material

SIZE_PX = 256  # side of every pattern image


@dataclass(frozen=True)
class Pattern:
    """A named seamless luminance pattern covering ``tile_m`` x ``tile_m`` metres."""

    name: str
    tile_m: float
    draw: Callable[[np.random.Generator, int], np.ndarray]  # (rng, px) -> floats in [0, 1]
    seed: int


# --- noise helpers ---------------------------------------------------------------------------
def _frequencies(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Integer spatial frequencies (cycles per image) along rows (v) and columns (u)."""
    f = np.fft.fftfreq(n, d=1.0 / n)
    return f[:, None], f[None, :]


def periodic_noise(
    rng: np.random.Generator, n: int, cycles_u: float, cycles_v: float, roughness: float = 0.0
) -> np.ndarray:
    """Seamless smooth noise, zero mean and unit deviation, (n, n).

    White noise low-passed in the Fourier domain with a Gaussian whose widths are ``cycles_u``
    (along columns) and ``cycles_v`` (along rows) cycles per image; ``roughness`` > 0 adds a
    power-law tail (fractal detail) beyond the cut-off.
    """
    fv, fu = _frequencies(n)
    radius = np.sqrt((fu / cycles_u) ** 2 + (fv / cycles_v) ** 2)
    gain = np.exp(-0.5 * radius**2)
    if roughness > 0.0:
        gain = gain + roughness * np.where(radius > 0, 1.0 / np.maximum(radius, 1.0) ** 1.6, 0.0)
    gain[0, 0] = 0.0
    field = np.real(np.fft.ifft2(np.fft.fft2(rng.standard_normal((n, n))) * gain))
    return field / max(float(field.std()), 1e-12)


def fractal_noise(rng: np.random.Generator, n: int, base_cycles: float, octaves: int) -> np.ndarray:
    """Sum of :func:`periodic_noise` octaves (each twice the frequency, half the weight)."""
    total = np.zeros((n, n))
    for k in range(octaves):
        total += 0.5**k * periodic_noise(rng, n, base_cycles * 2**k, base_cycles * 2**k)
    return total / max(float(total.std()), 1e-12)


def _grid(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Pixel-centre coordinates in [0, 1): u along columns, v along rows, each (n, n)."""
    t = (np.arange(n) + 0.5) / n
    return np.meshgrid(t, t, indexing="xy")


def _smoothstep(edge0: float, edge1: float, x: np.ndarray) -> np.ndarray:
    t = np.clip((x - edge0) / (edge1 - edge0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def _cells(rng: np.random.Generator, n: int, count: int) -> tuple[np.ndarray, np.ndarray]:
    """Periodic Worley noise on a ``count`` x ``count`` jittered grid: the distance to the
    nearest and second-nearest feature point (in cell units), each (n, n)."""
    jitter = rng.uniform(0.1, 0.9, size=(count, count, 2))
    u, v = _grid(n)
    cu, cv = u * count, v * count
    iu, iv = np.floor(cu).astype(int), np.floor(cv).astype(int)
    distances = []
    for dv in (-1, 0, 1):
        for du in (-1, 0, 1):
            ju, jv = iu + du, iv + dv
            point = jitter[jv % count, ju % count]
            distances.append(np.hypot(ju + point[..., 0] - cu, jv + point[..., 1] - cv))
    ordered = np.sort(np.stack(distances), axis=0)
    return ordered[0], ordered[1]


# --- the patterns ----------------------------------------------------------------------------
def _wood_field(rng: np.random.Generator, n: int, rings: int, warp: float) -> np.ndarray:
    """Wood with the grain along u: growth rings that wave gently along the board (the bend
    varies mostly along the grain, so rings rarely close into loops), each ring darkening
    towards its late wood, uneven ring widths, fine fibres and pores along the grain."""
    bend = periodic_noise(rng, n, 1.0, 0.6) + 0.15 * periodic_noise(rng, n, 2.0, 1.5)
    spacing = periodic_noise(rng, n, 0.3, 4.0)  # uneven ring widths, constant along the grain
    _, v = _grid(n)
    phase = rings * v + warp * bend + 0.6 * spacing
    ring = phase - np.floor(phase)
    late = ring**2.5 * (1.0 - _smoothstep(0.93, 1.0, ring))
    fibres = periodic_noise(rng, n, 1.0, n / 3.0)
    streaks = periodic_noise(rng, n, 0.7, n / 12.0)
    pores = periodic_noise(rng, n, 10.0, n / 2.5)
    tone = periodic_noise(rng, n, 0.8, 2.0)
    return (
        0.92
        - 0.13 * late
        + 0.03 * fibres
        + 0.03 * streaks
        + 0.03 * np.clip(pores, -2.5, -0.8)
        + 0.03 * tone
    )


def _wood(rng: np.random.Generator, n: int) -> np.ndarray:
    return _wood_field(rng, n, rings=12, warp=1.4)


def _planks(rng: np.random.Generator, n: int) -> np.ndarray:
    """Floor boards along u: 8 per image across, one end joint per row, staggered."""
    wood = _wood_field(rng, n, rings=40, warp=2.5)
    rows = 8
    board_px = n // rows
    out = np.empty((n, n))
    cols = np.arange(n)
    for r in range(rows):
        band = slice(r * board_px, (r + 1) * board_px)
        end = int(rng.integers(n))
        shifts = rng.integers(n, size=(2, 2))
        shade = rng.uniform(-0.05, 0.03, size=2)
        first = np.roll(np.roll(wood, shifts[0, 0], axis=1), shifts[0, 1], axis=0)[band]
        second = np.roll(np.roll(wood, shifts[1, 0], axis=1), shifts[1, 1], axis=0)[band]
        # The board that wraps from `end` round to `end` again is one board; a joint at `end`.
        joint_side = ((cols - end) % n) < (n // 2)
        out[band] = np.where(joint_side[None, :], first + shade[0], second + shade[1])
        out[band][:, end] = 0.45
        out[band][:, (end + n // 2) % n] = 0.45
        out[r * board_px] = np.minimum(out[r * board_px], 0.5)
    return out


def _fabric(rng: np.random.Generator, n: int) -> np.ndarray:
    """Plain weave: warp and weft threads crossing over and under, yarn heathering, slubs."""
    period = 8  # pixels per thread pair
    u, v = np.meshgrid(np.arange(n), np.arange(n), indexing="xy")
    over = ((u // (period // 2)) + (v // (period // 2))) % 2 == 0
    across_u = np.sin(np.pi * ((v % (period // 2)) + 0.5) / (period // 2))
    across_v = np.sin(np.pi * ((u % (period // 2)) + 0.5) / (period // 2))
    thread = np.where(over, across_u, across_v)
    heather = periodic_noise(rng, n, 10.0, 10.0)
    slubs = periodic_noise(rng, n, 3.0, n / 6.0)
    lum = 0.72 + 0.22 * thread + 0.04 * heather + 0.025 * slubs
    return lum


def _velvet(rng: np.random.Generator, n: int) -> np.ndarray:
    """Crushed pile: soft patches where the nap turns to the light, a faint fine nap."""
    patches = periodic_noise(rng, n, 4.0, 3.0) + 0.5 * periodic_noise(rng, n, 9.0, 7.0)
    nap = periodic_noise(rng, n, n / 4.0, n / 4.0)
    return 0.88 + 0.025 * patches + 0.015 * nap


def _leather(rng: np.random.Generator, n: int) -> np.ndarray:
    """Pebbled grain: small rounded cells of a periodic Worley pattern, soft creases between
    them, and a slow mottle."""
    near, second = _cells(rng, n, 36)
    crease = 1.0 - _smoothstep(0.0, 0.25, second - near)
    dome = 1.0 - np.clip(near, 0.0, 1.0) ** 2
    mottle = periodic_noise(rng, n, 3.0, 3.0)
    return 0.86 + 0.06 * dome - 0.07 * crease + 0.03 * mottle


def _marble(rng: np.random.Generator, n: int) -> np.ndarray:
    """White marble: cloudy background crossed by thin meandering veins."""
    u, v = _grid(n)
    turbulence = fractal_noise(rng, n, 2.0, 5)
    main = np.sin(2.0 * np.pi * (2 * u + 1 * v) + 1.6 * turbulence)
    fine = np.sin(2.0 * np.pi * (1 * u - 3 * v) + 2.4 * fractal_noise(rng, n, 3.0, 4))
    cloud = fractal_noise(rng, n, 3.0, 4)
    veins = 0.30 * np.exp(-((main / 0.07) ** 2)) + 0.14 * np.exp(-((fine / 0.04) ** 2))
    return 0.95 + 0.035 * cloud - veins


def _tile(rng: np.random.Generator, n: int) -> np.ndarray:
    """Square ceramic tiles, 4 x 4 per image, separated by grout joints."""
    count, grout = 4, 2
    cell = n // count
    u, v = np.meshgrid(np.arange(n), np.arange(n), indexing="xy")
    iu, iv = u // cell, v // cell
    shade = rng.uniform(-0.012, 0.012, size=(count, count))[iv, iu]
    edge = np.minimum(
        np.minimum(u % cell, cell - 1 - u % cell), np.minimum(v % cell, cell - 1 - v % cell)
    )
    glaze = periodic_noise(rng, n, 6.0, 6.0)
    lum = 0.93 + shade + 0.012 * glaze - 0.04 * (1.0 - _smoothstep(grout, grout + 3, edge))
    grout_noise = periodic_noise(rng, n, 40.0, 40.0)
    return np.where(edge < grout, 0.62 + 0.03 * grout_noise, lum)


def _brick(rng: np.random.Generator, n: int) -> np.ndarray:
    """Running-bond brickwork: 6 courses of 2 bricks per image, light mortar joints."""
    courses, per_course, mortar = 6, 2, 5
    course_px = n / courses
    brick_px = n / per_course
    u, v = np.meshgrid(np.arange(n) + 0.5, np.arange(n) + 0.5, indexing="xy")
    row = np.floor(v / course_px).astype(int)
    shifted = (u + (row % 2) * brick_px / 2.0) % n
    col = np.floor(shifted / brick_px).astype(int)
    dv = np.minimum(v - row * course_px, (row + 1) * course_px - v)
    du = np.minimum(shifted - col * brick_px, (col + 1) * brick_px - shifted)
    edge = np.minimum(du, dv)
    shade = rng.uniform(-0.10, 0.06, size=(courses, per_course))[row % courses, col % per_course]
    grit = periodic_noise(rng, n, 30.0, 30.0)
    blotch = periodic_noise(rng, n, 6.0, 10.0)
    face = 0.62 + shade + 0.03 * grit + 0.04 * blotch
    face = face - 0.06 * (1.0 - _smoothstep(mortar / 2.0, mortar / 2.0 + 3.0, edge))
    joint = 0.98 + 0.02 * periodic_noise(rng, n, 50.0, 50.0)
    return np.where(edge < mortar / 2.0, joint, face)


def _carpet(rng: np.random.Generator, n: int) -> np.ndarray:
    """Loop pile: dense fine speckle over soft tufts and slight mottling."""
    speckle = periodic_noise(rng, n, n / 3.0, n / 3.0)
    tufts = periodic_noise(rng, n, n / 12.0, n / 12.0)
    mottle = periodic_noise(rng, n, 4.0, 4.0)
    return 0.86 + 0.06 * speckle + 0.05 * tufts + 0.03 * mottle


def _concrete(rng: np.random.Generator, n: int) -> np.ndarray:
    """Cast concrete: multi-scale cloudy noise and sparse dark pores."""
    cloud = fractal_noise(rng, n, 3.0, 6)
    pores = periodic_noise(rng, n, n / 4.0, n / 4.0)
    pits = np.clip(pores - 2.6, 0.0, None)
    return 0.88 + 0.05 * cloud - 0.25 * pits


PATTERNS: dict[str, Pattern] = {
    p.name: p
    for p in (
        Pattern("wood", 0.5, _wood, 11),
        Pattern("planks", 1.6, _planks, 12),
        Pattern("fabric", 0.06, _fabric, 13),
        Pattern("velvet", 0.4, _velvet, 14),
        Pattern("leather", 0.2, _leather, 15),
        Pattern("marble", 0.8, _marble, 16),
        Pattern("tile", 1.2, _tile, 17),
        Pattern("brick", 0.45, _brick, 18),
        Pattern("carpet", 0.25, _carpet, 19),
        Pattern("concrete", 1.0, _concrete, 20),
    )
}


# --- images and PNG --------------------------------------------------------------------------
@functools.cache
def pattern_image(name: str) -> np.ndarray:
    """The pattern ``name`` as an (n, n) uint8 luminance image (read-only)."""
    pattern = PATTERNS[name]
    rng = np.random.default_rng(pattern.seed)
    lum = np.clip(pattern.draw(rng, SIZE_PX), 0.0, 1.0)
    image = np.round(lum * 255.0).astype(np.uint8)
    image.setflags(write=False)
    return image


@functools.cache
def pattern_png(name: str) -> bytes:
    """The PNG bytes of pattern ``name`` (greyscale, 8 bits, byte-deterministic)."""
    return png_bytes(pattern_image(name))


def pattern_mean(name: str) -> float:
    """The mean luminance of pattern ``name`` in [0, 1]."""
    return float(pattern_image(name).mean()) / 255.0


def tinted(rgba: tuple[float, float, float, float], name: str) -> tuple[float, ...]:
    """The material colour that, multiplied by pattern ``name``, averages to ``rgba``'s colour
    (each channel capped at 1; alpha kept), rounded to 4 decimals."""
    mean = pattern_mean(name)
    rgb = [min(1.0, c / mean) for c in rgba[:3]]
    return tuple(round(v, 4) for v in (*rgb, rgba[3]))


# --- choosing a pattern by words -------------------------------------------------------------
_WORDS: tuple[tuple[str, frozenset[str]], ...] = (
    # Order matters: the first family with a matching word wins ("wool carpet" is carpet).
    ("carpet", frozenset({"carpet", "carpeted", "carpeting", "rug", "sisal"})),
    ("brick", frozenset({"brick", "bricks", "brickwork"})),
    ("marble", frozenset({"marble"})),
    ("tile", frozenset({"tile", "tiles", "tiled", "tiling"})),
    ("leather", frozenset({"leather", "suede", "tolex"})),
    ("velvet", frozenset({"velvet", "plush", "velour"})),
    (
        "fabric",
        frozenset(
            {
                "fabric", "linen", "cotton", "wool", "woollen", "denim", "canvas", "felt",
                "tweed", "upholstery", "upholstered", "cloth", "nylon", "seagrass", "burlap",
            }
        ),
    ),
    (
        "wood",
        frozenset(
            {
                "wood", "wooden", "oak", "walnut", "pine", "ash", "cherry", "maple", "teak",
                "mahogany", "birch", "ebony", "bamboo", "beech", "plywood", "timber", "hardwood",
                "parquet", "veneer",
            }
        ),
    ),
    (
        "concrete",
        frozenset({"concrete", "cement", "stone", "slate", "granite", "sandstone", "terrazzo"}),
    ),
)  # fmt: skip
PLAIN_WORDS = frozenset({"plain", "paint", "painted", "lacquer", "lacquered", "glass", "metal"})


def words_of(text: str) -> list[str]:
    """Lower-case words of ``text`` (``_``, ``-`` and spaces separate them)."""
    return re.findall(r"[a-z]+", text.lower())


def pattern_for_words(words: list[str]) -> str | None:
    """The pattern a list of words names (see :data:`_WORDS`), or None."""
    found = set(words)
    for name, vocabulary in _WORDS:
        if found & vocabulary:
            return name
    return None


def pattern_for_name(name: str) -> str | None:
    """The pattern for a scene material called ``name`` (``oak_floor``, ``white_tile``,
    ``carpet_grey``), or None for a plain one (paints, ``*_default``, glass, metal, and any name
    with ``plain`` in it).

    Wood named for a floor, a wall panel or a ceiling is laid as boards (``planks``).
    """
    words = words_of(name)
    if not words or words[-1] == "default" or PLAIN_WORDS & set(words):
        return None
    pattern = pattern_for_words(words)
    if pattern == "wood" and {"floor", "floors", "panel", "ceiling", "boards"} & set(words):
        return "planks"
    return pattern


@dataclass(frozen=True)
class SurfaceLook:
    """A procedural look for a room-surface material: its PNG, tile size and tinted colour."""

    pattern: str
    png: bytes
    tile_m: float
    rgba: tuple[float, ...]


def procedural_look(name: str, material: Material) -> SurfaceLook | None:
    """The pattern a scene material called ``name`` wears when it brings no texture of its own
    (``oak_floor`` -> planks, ``white_tile`` -> tile, ``carpet_grey`` -> carpet), or None: a
    material with a texture, a plain one (paint, ``*_default``), or one whose name contains
    ``plain`` keeps its look."""
    if material.texture is not None:
        return None
    pattern = pattern_for_name(name)
    if pattern is None:
        return None
    return SurfaceLook(
        pattern, pattern_png(pattern), PATTERNS[pattern].tile_m, tinted(material.rgba, pattern)
    )
