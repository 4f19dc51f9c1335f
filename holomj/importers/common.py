"""Pieces every importer shares: building spec models with input-located errors, finishing the
scene, the safety net that turns stray Python errors into HolomjErrors, and opening snapping."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from holomj.errors import AssetNotFoundError, SpecError
from holomj.library.store import AssetLibrary
from holomj.spec.base import field_path
from holomj.spec.scene import SceneSpec
from holomj.spec.walls import Wall, find_wall_for_opening

ModelT = TypeVar("ModelT", bound=BaseModel)
ResultT = TypeVar("ResultT")

_SNAP_ALONG = 0.02  # metres an opening may be pushed along its wall to fit
_ON_WALL = 0.05  # metres an opening's centre may sit off the wall line


def join_path(path: str, sub: str) -> str:
    """``doors[2]`` + ``width`` -> ``doors[2].width``; ``rooms`` + ``[1]`` -> ``rooms[1]``."""
    if not path:
        return sub
    if not sub or sub == "<root>":
        return path
    return f"{path}{sub}" if sub.startswith("[") else f"{path}.{sub}"


def build_model(model: type[ModelT], data: dict[str, Any], source: str, path: str) -> ModelT:
    """Validate ``data`` as ``model``; errors name ``source`` and the input's JSON ``path``."""
    try:
        return model.model_validate(data)
    except ValidationError as err:
        first = err.errors(include_url=False)[0]
        loc = tuple(p for p in first.get("loc", ()) if not _union_tag(p))
        where = join_path(path, field_path(loc) if loc else "")
        raise SpecError(first.get("msg", "invalid value"), where=f"{source}: {where}") from None
    except SpecError as err:
        raise err.located(f"{source}: {path}") from None


def _union_tag(part: int | str) -> bool:
    return isinstance(part, str) and ("[" in part or part in {"float", "int", "str", "tuple"})


def finish_scene(fields: dict[str, Any], library: AssetLibrary, source: str) -> SceneSpec:
    """Build the SceneSpec (errors name ``source``) and check every object's asset exists."""
    try:
        scene = SceneSpec.model_validate(fields)
    except ValidationError as err:
        first = err.errors(include_url=False)[0]
        loc = tuple(p for p in first.get("loc", ()) if not _union_tag(p))
        raise SpecError(
            f"imported scene is invalid: {first.get('msg', 'invalid value')}",
            where=f"{source}: {field_path(loc)}",
        ) from None
    except SpecError as err:
        raise err.located(f"{source}: imported scene") from None
    check_assets(scene, library, source)
    return scene


def check_assets(scene: SceneSpec, library: AssetLibrary, source: str) -> None:
    """Raise AssetNotFoundError naming ``objects[i].asset`` for an asset the library lacks."""
    for index, obj in enumerate(scene.objects):
        if obj.asset not in library:
            try:
                library.get(obj.asset)
            except AssetNotFoundError as err:
                raise err.located(f"{source}: objects[{index}].asset") from None


def snap_opening(
    walls: Sequence[Wall],
    rooms: Sequence[str],
    position: tuple[float, float],
    width: float,
) -> tuple[tuple[float, float], Wall, float]:
    """Put an opening's centre exactly on its wall line, nudging it up to 2 cm along the wall
    to fit; returns the position, the wall and the distance of the centre along it.

    Raises the SpecError of :func:`find_wall_for_opening` when it cannot be placed.
    """
    wanted = tuple(sorted(set(rooms)))
    best: tuple[float, Wall, float] | None = None
    for wall in walls:
        if wall.rooms != wanted:
            continue
        t, off = wall.locate(position)
        if abs(off) > _ON_WALL or t < -_ON_WALL or t > wall.length + _ON_WALL:
            continue
        lo, hi = width / 2, wall.length - width / 2
        if lo > hi + 1e-9:
            continue
        clamped = min(max(t, lo), hi)
        shift = abs(clamped - t)
        if shift <= _SNAP_ALONG + 1e-9 and (best is None or shift < best[0]):
            best = (shift, wall, clamped)
    if best is not None:
        _, wall, t = best
        x, y = wall.point_at(t)
        return (round(x, 9), round(y, 9)), wall, t
    wall, t = find_wall_for_opening(walls, wanted, position, width)
    return position, wall, t


def clamp_noise(value: float, lo: float, hi: float, tol: float) -> float:
    """``value`` pulled into ``[lo, hi]`` when it is outside by at most ``tol``."""
    if lo - tol <= value < lo:
        return lo
    if hi < value <= hi + tol:
        return hi
    return value


LIGHT_KINDS = ("point", "spot", "directional")


def light_kind(node: Any) -> str:
    """The ``type`` of a light node (default point), checked against holomj's light kinds."""
    kind = node.str_("type", "point").lower()
    if kind not in LIGHT_KINDS:
        raise node.get("type").error(
            f"unknown light type {kind!r}", fix="use point, spot or directional"
        )
    return kind
