"""Dropping an object where the model pointed (step 5 of :mod:`holomj.jobs.pointing`):
spawn-and-drop on the hit surface cut down to a disc around the point, the object's footprint
radius plus 3 cm, then 8 cm when that finds no place.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from shapely.geometry import MultiPolygon, Point, Polygon

from holomj.errors import HolomjError
from holomj.library.store import AssetLibrary, LibraryAsset
from holomj.spec.scene import SceneSpec

CROP_MARGINS_M = (0.03, 0.08)
TINY = ((0.0, 0.0), (1e-4, 0.0), (0.0, 1e-4))


def drop_at(
    scene: SceneSpec,
    ctx: Any,
    receptacle_id: str,
    asset_id: str,
    hit: Any,
    seed: int,
    number: int,
    max_attempts: int,
) -> tuple[SceneSpec | None, dict[str, Any]]:
    """Spawn-and-drop ``asset_id`` on the surface ``hit.index`` near ``hit.point`` (see the
    module docstring): the new scene (None when it found no place) and the drop's record."""
    from holomj.physics.spawn import find_object, populate
    from holomj.seeds import stage_rng

    library = ctx.library
    receptacle = find_object(scene, receptacle_id)
    asset = library.get(receptacle.asset)
    small = library.get(asset_id).meta
    half_diag = 0.5 * math.hypot(small.size[0], small.size[1])
    reasons = []
    for margin in CROP_MARGINS_M:
        cropped = _cropped_library(library, receptacle, asset, hit, half_diag + margin)
        if cropped is None:
            reasons.append(f"within {margin * 100:.0f} cm: the surface is too small there")
            continue
        try:
            result = populate(
                scene,
                cropped,
                receptacle_id,
                [(asset_id, 1)],
                stage_rng(seed, "pointing", str(number), str(margin)),
                max_attempts=max_attempts,
                attach=ctx.attach,
            )
        except HolomjError as err:
            reasons.append(err.one_line())
            continue
        placement = result.placements[0]
        if placement.accepted and placement.final_pose is not None:
            final = placement.final_pose["position"]
            distance = math.hypot(final[0] - hit.point[0], final[1] - hit.point[1])
            return result.scene, {
                "object_id": placement.object_id,
                "asset": placement.asset,
                "attempts": placement.attempts,
                "final_position": final,
                "distance_m": round(distance, 4),
                "margin_m": margin,
                "reason": "placed",
            }
        reasons.append(f"within {margin * 100:.0f} cm: {placement.reason}")
    return None, {"reason": "; ".join(reasons) or "no place"}


def _cropped_library(
    library: AssetLibrary, receptacle: Any, asset: LibraryAsset, hit: Any, radius: float
) -> AssetLibrary | None:
    """``library`` with the receptacle's asset showing only the hit surface, cut to a disc of
    ``radius`` around the hit point (in the asset frame); the surfaces above it stay, shrunk to
    nothing, so the headroom under them still counts. None when the cut is empty."""
    from holomj.physics.surfaces_world import object_yaw
    from holomj.spec.assets import SupportSurface

    meta = asset.meta
    sx, sy, _ = receptacle.scale3
    yaw = object_yaw(receptacle)
    dx, dy = hit.point[0] - receptacle.position[0], hit.point[1] - receptacle.position[1]
    c, s = math.cos(-yaw), math.sin(-yaw)
    local = ((c * dx - s * dy) / sx, (s * dx + c * dy) / sy)
    surface = meta.surfaces[hit.index]
    disc = Point(local).buffer(radius / min(sx, sy), 32)
    cut = Polygon(surface.polygon).intersection(disc)
    if isinstance(cut, MultiPolygon):
        cut = max(cut.geoms, key=lambda g: g.area)
    if not isinstance(cut, Polygon) or cut.is_empty or cut.area < 1e-6:
        return None
    coords = [(round(x, 6), round(y, 6)) for x, y in np.asarray(cut.exterior.coords)[:-1]]
    surfaces = [SupportSurface(height=surface.height, polygon=coords, area_m2=float(cut.area))]
    for other in meta.surfaces:
        if other.height > surface.height + 1e-6:
            surfaces.append(SupportSurface(height=other.height, polygon=list(TINY), area_m2=1e-8))
    view = meta.model_copy(update={"surfaces": surfaces})
    assets = {aid: library.get(aid) for aid in library.ids()}
    assets[meta.id] = LibraryAsset(view, asset.root)
    return AssetLibrary(library.root, library.name, assets)
