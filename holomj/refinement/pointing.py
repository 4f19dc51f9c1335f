"""Placement by pointing: a pixel of a rendered view becomes a ray onto a receptacle's surface.

The camera is the one MuJoCo drew the view with (:class:`PinholeCamera`: the GL camera's
position, forward and up vectors, the vertical field of view ``fovy`` and the image size; the
horizontal field follows from the aspect ratio). Pixel ``(u, v)`` counts columns from the
left and rows from the top of the image, as the model sees it; its ray goes through the
pixel's centre. :func:`hit_surface` intersects the ray with the plane of each support surface
and keeps the first surface whose polygon holds the point.

The conversation (:func:`name_question`, :func:`point_question`, :func:`parse_name`,
:func:`parse_pixel`) asks the model first to name the next small object, then to point at
where it goes; answers are JSON, checked, never executed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from shapely.geometry import Point

from holomj.plan.llm_json import LLMResponseError, extract_json_object
from holomj.refinement.safety import looks_like_code

MAX_NAME_CHARS = 80


@dataclass(frozen=True)
class PinholeCamera:
    """A perspective camera: position, unit forward and up vectors (world frame), vertical
    field of view in degrees, and the image size in pixels."""

    position: tuple[float, float, float]
    forward: tuple[float, float, float]
    up: tuple[float, float, float]
    fovy_deg: float
    width: int
    height: int

    def _axes(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        forward = np.asarray(self.forward, dtype=float)
        forward /= np.linalg.norm(forward)
        up = np.asarray(self.up, dtype=float)
        up = up - forward * float(up @ forward)
        up /= np.linalg.norm(up)
        right = np.cross(forward, up)
        return forward, up, right

    @property
    def tan_half(self) -> tuple[float, float]:
        """tan of half the (horizontal, vertical) field of view."""
        tan_v = math.tan(math.radians(self.fovy_deg) / 2)
        return tan_v * self.width / self.height, tan_v

    def ray(self, u: float, v: float) -> tuple[np.ndarray, np.ndarray]:
        """(origin, unit direction) of the ray through the centre of pixel (u, v)."""
        forward, up, right = self._axes()
        tan_h, tan_v = self.tan_half
        x = (2.0 * (u + 0.5) / self.width - 1.0) * tan_h
        y = (1.0 - 2.0 * (v + 0.5) / self.height) * tan_v
        direction = forward + x * right + y * up
        return np.asarray(self.position, dtype=float), direction / np.linalg.norm(direction)

    def project(self, point: Sequence[float]) -> tuple[float, float] | None:
        """The pixel (u, v; fractional) where a world point appears; None behind the camera."""
        forward, up, right = self._axes()
        offset = np.asarray(point, dtype=float) - np.asarray(self.position, dtype=float)
        depth = float(offset @ forward)
        if depth <= 1e-9:
            return None
        tan_h, tan_v = self.tan_half
        x = float(offset @ right) / depth / tan_h
        y = float(offset @ up) / depth / tan_v
        return (x + 1.0) * self.width / 2 - 0.5, (1.0 - y) * self.height / 2 - 0.5

    def to_json(self) -> dict[str, Any]:
        """JSON-able form."""
        return {
            "position": [round(v, 5) for v in self.position],
            "forward": [round(v, 6) for v in self.forward],
            "up": [round(v, 6) for v in self.up],
            "fovy_deg": round(self.fovy_deg, 4),
            "width": self.width,
            "height": self.height,
        }


@dataclass(frozen=True)
class SurfaceHit:
    """Where a pixel's ray meets a support surface: its index and the world point."""

    index: int
    point: tuple[float, float, float]
    distance: float


def hit_surface(camera: PinholeCamera, u: float, v: float, surfaces: Sequence[Any]) -> SurfaceHit:
    """The first support surface (objects with ``index``, ``height`` and a world ``polygon``)
    the ray of pixel (u, v) meets inside its polygon; :class:`LLMResponseError` saying where the
    ray goes instead (fed back to the model)."""
    origin, direction = camera.ray(u, v)
    best: SurfaceHit | None = None
    misses: list[tuple[float, float, float]] = []
    for surface in surfaces:
        if direction[2] >= -1e-9:
            break
        t = (float(surface.height) - origin[2]) / direction[2]
        if t <= 0:
            continue
        point = origin + t * direction
        if surface.polygon.contains(Point(point[0], point[1])):
            if best is None or t < best.distance:
                best = SurfaceHit(
                    int(surface.index),
                    (float(point[0]), float(point[1]), float(point[2])),
                    float(t),
                )
        else:
            gap = surface.polygon.exterior.distance(Point(point[0], point[1]))
            misses.append((gap, float(point[0]), float(point[1])))
    if best is not None:
        return best
    if not misses:
        raise LLMResponseError(f"pixel ({u:g}, {v:g}) looks above the horizon, not at the surface")
    gap, x, y = min(misses)
    raise LLMResponseError(
        f"pixel ({u:g}, {v:g}) is not on the receptacle's surface: its ray passes "
        f"({x:.2f}, {y:.2f}), {gap:.2f} m outside it; point inside the surface"
    )


# --------------------------------------------------------------------------- conversation

SYSTEM = (
    "You place small objects on a piece of furniture in a 3D indoor scene, one at a time. You "
    "see a rendered view looking straight down at it. Answer with one JSON object and nothing "
    "else; never write code (answers with code are refused and nothing is ever executed)."
)


def name_question(
    instruction: str, receptacle: str, category: str, on_it: Sequence[str], left: int
) -> str:
    """The question that asks for the next object's name."""
    already = ", ".join(on_it) if on_it else "nothing"
    return (
        f"Instruction: {instruction}\n"
        f"The furniture is {receptacle} (a {category.replace('_', ' ')}). On it now: {already}. "
        f"Up to {left} more object(s) may be added.\n"
        'Name the next small object to put on it: answer {"object": "a short description, '
        'e.g. a red mug"}, or {"done": true} when the instruction is fulfilled.'
    )


def point_question(name: str, width: int, height: int) -> str:
    """The question that asks where the object goes."""
    return (
        f"Where should {name} go? Point at a free spot on the furniture's top surface in the "
        f'image ({width} x {height} pixels): answer {{"pixel": [u, v]}} with u the column '
        f"from the left edge (0 to {width - 1}) and v the row from the top edge "
        f"(0 to {height - 1})."
    )


def parse_name(content: str) -> str | None:
    """The object named in an answer; None for ``{"done": true}``."""
    data = extract_json_object(content)
    if data.get("done") is True and "object" not in data:
        return None
    name = data.get("object")
    if not isinstance(name, str) or not name.strip():
        raise LLMResponseError('expected {"object": "a short description"} or {"done": true}')
    name = " ".join(name.split())
    if len(name) > MAX_NAME_CHARS:
        raise LLMResponseError(f"the description is longer than {MAX_NAME_CHARS} characters")
    if looks_like_code(name):
        raise LLMResponseError("the description looks like code: describe an object in words")
    return name


def parse_pixel(content: str, width: int, height: int) -> tuple[int, int]:
    """The pixel of an answer ``{"pixel": [u, v]}``, inside the image."""
    data = extract_json_object(content)
    pixel = data.get("pixel")
    if (
        not isinstance(pixel, list)
        or len(pixel) != 2
        or not all(isinstance(p, (int, float)) and not isinstance(p, bool) for p in pixel)
    ):
        raise LLMResponseError('expected {"pixel": [u, v]} with two numbers')
    u, v = (float(p) for p in pixel)
    if not (math.isfinite(u) and math.isfinite(v)):
        raise LLMResponseError("the pixel must be two finite numbers")
    if not (0 <= u < width and 0 <= v < height):
        raise LLMResponseError(
            f"pixel ({u:g}, {v:g}) is outside the {width} x {height} image: u in [0, "
            f"{width - 1}], v in [0, {height - 1}]"
        )
    return int(u), int(v)
