"""Choosing a library asset for a foreign object: the asset itself, a stand-in, or a box.

1. The requested asset id is in the library: use it as it is.
2. Otherwise an asset of the object's category, then of the category's aliases
   (``holomj/data/category_facts.json``), then of the caller's stand-in categories (for THOR
   types, ``holomj/data/thor_types.json``), closest in size.
3. Otherwise ``builtin:box`` scaled to the object's size.

The object's size (x = depth, y = width, z = height, metres, in the object's own frame) is what
the caller knows from the source (the AI2-THOR asset table, a Holodeck footprint), else a typical
size of its category from ``holomj/data/category_facts.json``; unknown categories get a 0.5 m
cube and a warning.

Fitting (``fit=True``; the importers ask for it when the size is the original's true size)
----------------------------------------------------------------------------------------------
The stand-in is scaled per axis to the original's bounding box, so the object keeps its true
size, within limits that keep a stand-in recognisable:

* each axis factor within ``[SCALE_MIN, SCALE_MAX]`` = ``[0.5, 2.0]`` of the stand-in's size;
* the largest factor at most ``MAX_ASPECT_CHANGE`` = 2.5 times the smallest (the stand-in's
  proportions change by at most 2.5x).

Among a category's assets, those within the limits compete by size distance (sum of squared
log ratios). The source's yaw fixes where the object's front is, so a stand-in keeps its
orientation; only small props (placement ``object``, not wall or ceiling) may instead stand in
turned by 90° about Z (a pan whose handle was modelled along the other axis), and only when no
unturned asset of the category fits. When none of a category fits, the next category is tried;
when none fits at all, ``builtin:box`` scaled to the size is used and the substitution's reason
names the closest stand-in and the scale it would have needed. The
:class:`~holomj.importers.result.Substitution` records the scale used, the turn, the original
size and where that size came from.

Without fitting (SceneDef imports), the closest asset is used at scale 1, a 90° turn allowed in
the comparison as in :meth:`AssetLibrary.closest`.

Objects that open (``prefer_articulated``: THOR's ``CanOpen`` fridges, boxes, dryers...) first
look for an *articulated* asset (doors, drawers or lids on joints) among all those categories,
in the same order and with the same limits, and take the ordinary choice only when none fits:
an opening original gets a stand-in that opens whenever the library has one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from holomj.importers.frames import triple
from holomj.importers.result import Substitution
from holomj.library.store import BUILTIN_BOX, AssetLibrary, LibraryAsset, size_distance
from holomj.spec.categories import category_aliases, category_size, normalise_category

FALLBACK_SIZE = (0.5, 0.5, 0.5)
SCALE_MIN = 0.5  # smallest per-axis factor applied to a stand-in
SCALE_MAX = 2.0  # largest per-axis factor applied to a stand-in
MAX_ASPECT_CHANGE = 2.5  # largest factor / smallest factor
MIN_EXTENT = 0.005  # metres: thinner source extents (a credit card's 4.5 mm) are raised to this

Size = tuple[float, float, float]
Scale = float | tuple[float, float, float]


@dataclass(frozen=True)
class AssetChoice:
    """The asset used for an object, its scale, its height once scaled, and any substitution."""

    asset: str
    scale: Scale
    height: float
    substitution: Substitution | None
    turn_deg: float = 0.0  # the asset turns this much about Z within the object (0 or 90)


def fit_scale(asset_size: Size, target: Size) -> tuple[float, float, float] | None:
    """Per-axis factors taking ``asset_size`` to ``target``, or None beyond the limits."""
    scale = _raw_scale(asset_size, target)
    if min(scale) < SCALE_MIN or max(scale) > SCALE_MAX:
        return None
    if max(scale) > MAX_ASPECT_CHANGE * min(scale):
        return None
    return scale


def clamped_scale(scale: tuple[float, float, float]) -> tuple[float, float, float]:
    """The factors nearest to ``scale`` within the limits (each axis in ``[SCALE_MIN,
    SCALE_MAX]``, the largest at most ``MAX_ASPECT_CHANGE`` times the smallest)."""
    clamped = [min(max(f, SCALE_MIN), SCALE_MAX) for f in scale]
    low = min(clamped)
    return triple(round(min(f, low * MAX_ASPECT_CHANGE), 4) for f in clamped)


def _may_turn(asset: LibraryAsset) -> bool:
    """Small props may stand in turned by 90°; furniture keeps its front where the source has it."""
    placement = set(asset.meta.placement)
    return "object" in placement and not placement & {"wall", "ceiling"}


def _turned(size: tuple[float, float, float], turn: float) -> tuple[float, float, float]:
    """A size (or scale) seen from a frame turned by ``turn`` (0 or 90°) about Z."""
    return (size[1], size[0], size[2]) if turn else size


def _raw_scale(asset_size: Size, target: Size) -> tuple[float, float, float]:
    return triple(round(t / max(a, 1e-6), 4) for a, t in zip(asset_size, target))


def straight_distance(a: Size, b: Size) -> float:
    """Sum of squared log ratios of extents, axis by axis (no turn)."""
    return sum(math.log(max(p, 1e-3) / max(q, 1e-3)) ** 2 for p, q in zip(a, b))


def compact_scale(scale: tuple[float, float, float]) -> Scale:
    """One factor when all three are equal, else the three."""
    return scale[0] if scale[0] == scale[1] == scale[2] else scale


def candidate_categories(category: str, stand_ins: tuple[str, ...] = ()) -> list[str]:
    """The category, its aliases, then ``stand_ins``; each once (compared normalised)."""
    names = [category, *category_aliases().get(normalise_category(category), []), *stand_ins]
    seen: set[str] = set()
    result = []
    for name in names:
        key = normalise_category(name)
        if key and key not in seen:
            seen.add(key)
            result.append(name)
    return result


def choose_asset(
    library: AssetLibrary,
    *,
    object_id: str,
    requested: str,
    category: str,
    size: Size | None,
    fit: bool = False,
    stand_ins: tuple[str, ...] = (),
    size_source: str | None = None,
    prefer_articulated: bool = False,
    nearest_when_none_fits: bool = False,
) -> tuple[AssetChoice, str | None]:
    """Pick the asset for an object; also returns a warning when the size had to be guessed.

    ``fit``: scale a stand-in to ``size`` (see the module notes); ``stand_ins``: further
    categories to try after the category and its aliases; ``size_source``: where ``size`` came
    from, for the substitution record; ``prefer_articulated``: the original opens, so an
    articulated asset of any of the categories goes first (see the module notes);
    ``nearest_when_none_fits``: when no asset of the categories fits within the scale limits,
    the closest one is scaled as far towards ``size`` as the limits allow (an object of its
    own kind a little off its size rather than a box of it).
    """
    if requested and requested in library:
        return AssetChoice(requested, 1.0, library.get(requested).meta.size[2], None), None
    warning = None
    if size is None:
        size = category_size(category) if category else None
        size_source = "category" if size is not None else None
    if size is None:
        size = FALLBACK_SIZE
        size_source = "guess"
        warning = (
            f"object {object_id!r}: no size known for category {category!r}; assuming a 0.5 m cube"
        )
    size = (max(size[0], MIN_EXTENT), max(size[1], MIN_EXTENT), max(size[2], MIN_EXTENT))

    search = _Search(
        library,
        category,
        size,
        fit,
        Substitution(
            object_id=object_id,
            requested_asset=requested,
            category=category,
            used_asset="",
            reason="",
            source_size=size,
            size_source=size_source,
        ),
    )
    names = candidate_categories(category, stand_ins) if category else []
    for articulated_only in (True, False) if prefer_articulated else (False,):
        for name in names:
            found = search.in_category(name, articulated_only)
            if found is not None:
                return found, warning
    return search.fallback(nearest_when_none_fits), warning


class _Search:
    """The search of :func:`choose_asset` over candidate categories, remembering the closest
    asset that did not fit (for the fallback and its reason)."""

    def __init__(
        self, library: AssetLibrary, category: str, size: Size, fit: bool, record: Substitution
    ) -> None:
        self.library = library
        self.category = category
        self.size = size
        self.fit = fit
        self.record = record  # the substitution's fixed fields
        self.missed: tuple[float, str, tuple[float, float, float]] | None = None

    def substitution(self, used: str, reason: str, scale: Scale, turn: float = 0.0) -> Substitution:
        """The record of using ``used`` for the object."""
        return replace(self.record, used_asset=used, reason=reason, scale=scale, turn_deg=turn)

    def _what(self, name: str, articulated_only: bool) -> str:
        same = normalise_category(name) == normalise_category(self.category)
        if articulated_only and same:
            return "same category, articulated (the original opens), "
        if articulated_only:
            return f"articulated stand-in of category {name!r} (the original opens), "
        return "same category, " if same else f"stand-in of category {name!r}, "

    def in_category(self, name: str, articulated_only: bool) -> AssetChoice | None:
        """The best asset of category ``name`` (only articulated ones when asked), or None."""
        size = self.size
        candidates = [
            a
            for a in self.library.by_category(name)
            if a.meta.id != BUILTIN_BOX and (a.meta.articulated or not articulated_only)
        ]
        if not candidates:
            return None
        what = self._what(name, articulated_only)
        if not self.fit:
            stand_in = min(candidates, key=lambda a: (size_distance(a.meta.size, size), a.meta.id))
            sub = self.substitution(stand_in.meta.id, f"not in library; {what}closest size", 1.0)
            return AssetChoice(stand_in.meta.id, 1.0, stand_in.meta.size[2], sub)
        fitting = []
        for asset in candidates:
            for turn in (0.0, 90.0) if _may_turn(asset) else (0.0,):
                own = _turned(asset.meta.size, turn)
                distance = straight_distance(own, size)
                scale = fit_scale(own, size)
                if scale is not None:
                    fitting.append((turn, distance, asset.meta.id, asset, _turned(scale, turn)))
                elif not articulated_only and turn == 0.0 and self._closer(distance):
                    self.missed = (distance, asset.meta.id, _raw_scale(own, size))
        if not fitting:
            return None
        turn, _, asset_id, asset, scale = min(fitting, key=lambda f: f[:3])
        turned = ", turned 90°" if turn else ""
        reason = f"not in library; {what}scaled to the source size{turned}"
        used = compact_scale(scale)
        height = round(asset.meta.size[2] * scale[2], 9)
        return AssetChoice(
            asset_id, used, height, self.substitution(asset_id, reason, used, turn), turn
        )

    def _closer(self, distance: float) -> bool:
        return self.missed is None or distance < self.missed[0]

    def fallback(self, nearest: bool) -> AssetChoice:
        """When no asset fitted: the closest one at the nearest allowed scale (``nearest``),
        else ``builtin:box`` of the object's size."""
        category, missed = self.category, self.missed
        if missed is not None and nearest:
            asset = self.library.get(missed[1])
            scale = clamped_scale(missed[2])
            reason = (
                f"not in library; no asset of category {category!r} fits within the scale "
                f"limits: closest {missed[1]!r} scaled by the nearest allowed factors"
            )
            used = compact_scale(scale)
            height = round(asset.meta.size[2] * scale[2], 9)
            return AssetChoice(missed[1], used, height, self.substitution(missed[1], reason, used))
        if missed is not None:
            factors = ", ".join(f"{s:g}" for s in missed[2])
            reason = (
                f"no asset of category {category!r} fits within the scale limits (closest "
                f"{missed[1]!r} would need ({factors})); box of the object's size"
            )
        else:
            reason = f"no asset of category {category!r}; box of the object's size"
        box_height = self.library.get(BUILTIN_BOX).meta.size[2] * self.size[2]
        sub = self.substitution(BUILTIN_BOX, reason, self.size)
        return AssetChoice(BUILTIN_BOX, self.size, box_height, sub)
