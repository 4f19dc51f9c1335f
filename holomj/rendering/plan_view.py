"""The annotated plan: the top-down render with rooms, objects, doors and windows drawn on it.

Room outlines with their names and types, every object's bounding box on the floor (furniture
and small objects in two colours) with its id, doors and windows as thick strokes on their
walls, and below the drawing a strip with the legend and a scale bar. Pure drawing (PIL) on
data computed elsewhere.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

from PIL import Image, ImageDraw, ImageFont
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.ops import polylabel, unary_union

from holomj.rendering.cameras import TopCamera
from holomj.spec.scene import Door, SceneSpec
from holomj.spec.walls import find_wall_for_opening

ROOM_COLOR = (40, 40, 40, 255)
FURNITURE_COLOR = (214, 69, 30, 255)
SMALL_COLOR = (30, 90, 200, 255)
DOOR_COLOR = (120, 60, 20, 255)
WINDOW_COLOR = (0, 170, 220, 255)
LABEL_BOX = (255, 255, 255, 200)
FADE = 0.3  # blend the render this much towards white so the drawing stands out


@dataclass(frozen=True)
class PlanViewObject:
    """An object as the plan draws it: its id, footprint and whether it rests on another."""

    id: str
    footprint: Polygon
    small: bool


@dataclass(frozen=True)
class PlanViewOpening:
    """A door or window as a segment on its wall (world x/y)."""

    id: str
    kind: str  # "door" or "window"
    start: tuple[float, float]
    end: tuple[float, float]


def openings(scene: SceneSpec) -> list[PlanViewOpening]:
    """Every door and window of ``scene`` as a segment on the wall it sits in."""
    walls = scene.walls
    result = []
    for item in scene.openings:
        if isinstance(item, Door):
            width, kind = item.effective_width, "door"
        else:
            width, kind = item.width, "window"
        wall, t = find_wall_for_opening(walls, item.rooms, item.position, width)
        start, end = wall.point_at(t - width / 2), wall.point_at(t + width / 2)
        result.append(PlanViewOpening(item.id, kind, start, end))
    return result


@lru_cache(maxsize=16)
def _font(size: int) -> ImageFont.ImageFont | ImageFont.FreeTypeFont:
    try:
        return ImageFont.load_default(size=size)
    except (TypeError, ValueError, OSError):  # Pillow without FreeType: fixed bitmap font
        return ImageFont.load_default()


def draw_plan(
    top: Image.Image,
    camera: TopCamera,
    scene: SceneSpec,
    objects: Sequence[PlanViewObject],
) -> Image.Image:
    """The annotated plan drawn over the top-down render ``top`` (made with ``camera``), with
    a legend strip below it (the plan is taller than ``top`` by the strip; pixels above the
    strip map to the world as ``camera`` says)."""
    base = Image.blend(top.convert("RGB"), Image.new("RGB", top.size, "white"), FADE)
    overlay = Image.new("RGBA", top.size, (0, 0, 0, 0))
    draw = ImageDraw.Draw(overlay)
    unit = max(1.0, min(top.size) / 480)
    px_per_m = 1.0 / camera.metres_per_pixel
    line = max(1, round(1.5 * unit))
    small_font, room_font = _font(max(8, round(10 * unit))), _font(max(10, round(15 * unit)))

    for room in scene.rooms:
        points = [camera.to_pixel(x, y) for x, y in room.polygon]
        draw.polygon(points, outline=ROOM_COLOR, width=line)
    stroke = max(3, round(0.12 * px_per_m))
    for opening in openings(scene):
        color = DOOR_COLOR if opening.kind == "door" else WINDOW_COLOR
        ends = [camera.to_pixel(*opening.start), camera.to_pixel(*opening.end)]
        draw.line(ends, fill=color, width=stroke)
    furniture = [o for o in objects if not o.small]
    small = [o for o in objects if o.small]  # drawn last, boxed but not named: ids would pile up
    for obj in furniture:
        draw.polygon(_pixels(camera, obj.footprint), outline=FURNITURE_COLOR, width=line)
    for obj in furniture:
        centre = obj.footprint.centroid
        at = camera.to_pixel(centre.x, centre.y)
        if any(obj.footprint.intersects(o.footprint) for o in small):  # name it above its box
            top_row = min(v for _, v in _pixels(camera, obj.footprint))
            box = draw.textbbox((0, 0), obj.id, font=small_font)
            at = (at[0], top_row - (box[3] - box[1]) / 2 - 4)
        _label(draw, at, obj.id, small_font, FURNITURE_COLOR)
    for obj in small:
        draw.polygon(_pixels(camera, obj.footprint), outline=SMALL_COLOR, width=line)
    taken = unary_union([o.footprint.buffer(0.15) for o in objects]) if objects else None
    for room in scene.rooms:
        spot = _label_spot(Polygon(room.polygon), taken)
        text = room.id if room.type in ("room", room.id) else f"{room.id}\n({room.type})"
        _label(draw, camera.to_pixel(spot[0], spot[1]), text, room_font, ROOM_COLOR)
    drawn = Image.alpha_composite(base.convert("RGBA"), overlay).convert("RGB")
    legend = _legend(top.size, px_per_m, small_font, unit)
    plan = Image.new("RGB", (top.width, top.height + legend.height), "white")
    plan.paste(drawn, (0, 0))
    plan.paste(legend, (0, top.height))
    return plan


def _pixels(camera: TopCamera, shape: Polygon) -> list[tuple[float, float]]:
    return [camera.to_pixel(x, y) for x, y in list(shape.exterior.coords)[:-1]]


def _label_spot(room: Polygon, taken: BaseGeometry | None) -> tuple[float, float]:
    """The point of the room farthest from its walls and from every object."""
    free = room.difference(taken) if taken is not None else room
    if isinstance(free, MultiPolygon):
        free = max(free.geoms, key=lambda g: g.area)
    if not isinstance(free, Polygon) or free.area < 0.05 * room.area:
        free = room
    spot = polylabel(free, tolerance=0.05)
    return spot.x, spot.y


def _label(
    draw: ImageDraw.ImageDraw,
    at: tuple[float, float],
    text: str,
    font: ImageFont.ImageFont | ImageFont.FreeTypeFont,
    color: tuple[int, int, int, int],
) -> None:
    box = draw.multiline_textbbox(at, text, font=font, anchor="mm", align="center")
    pad = 2
    draw.rectangle((box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad), fill=LABEL_BOX)
    draw.multiline_text(at, text, font=font, fill=color, anchor="mm", align="center")


def _legend(
    size: tuple[int, int],
    px_per_m: float,
    font: ImageFont.ImageFont | ImageFont.FreeTypeFont,
    unit: float,
) -> Image.Image:
    """A strip with a swatch per colour and a scale bar, to go below the plan."""
    items = [
        ("furniture", FURNITURE_COLOR),
        ("small object", SMALL_COLOR),
        ("door", DOOR_COLOR),
        ("window", WINDOW_COLOR),
    ]
    swatch, gap = round(10 * unit), round(8 * unit)
    strip = Image.new("RGB", (size[0], swatch + 2 * gap), "white")
    draw = ImageDraw.Draw(strip)
    x, middle = gap, strip.height / 2
    for name, color in items:
        draw.rectangle((x, middle - swatch / 2, x + swatch, middle + swatch / 2), fill=color)
        x += swatch + 4
        draw.text((x, middle), name, font=font, fill=ROOM_COLOR, anchor="lm")
        x += round(draw.textlength(name, font=font)) + 2 * gap
    bar_m = _scale_bar_metres(size[0] / px_per_m)
    bar_px = bar_m * px_per_m
    draw.line([(x, middle), (x + bar_px, middle)], fill=ROOM_COLOR, width=max(2, round(2 * unit)))
    for end in (x, x + bar_px):
        draw.line([(end, middle - swatch / 3), (end, middle + swatch / 3)], fill=ROOM_COLOR)
    draw.text((x + bar_px + 4, middle), f"{bar_m:g} m", font=font, fill=ROOM_COLOR, anchor="lm")
    return strip


def _scale_bar_metres(view_width_m: float) -> float:
    """A round length (1, 2 or 5 times a power of ten) near a fifth of the view's width."""
    goal = view_width_m / 5
    power = 10 ** math.floor(math.log10(goal))
    return max(f * power for f in (1, 2, 5) if f * power <= goal)
