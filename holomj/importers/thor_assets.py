"""AI2-THOR assets and object types, as ProcTHOR houses name them.

Two tables ship with holomj:

* ``holomj/data/thor_assets.json``: every AI2-THOR asset used by ProcTHOR houses (1,653 assetIds,
  109 object types) with its object type, axis-aligned bounding box and the ``CanOpen`` /
  ``Receptacle`` flags. Derived from allenai/procthor (Apache-2.0, commit and licence in the
  file's ``_source`` entry and ``holomj/data/LICENSE-procthor-Apache-2.0.txt``).
* ``holomj/data/thor_types.json``: each of the 109 THOR object types -> its holomj category,
  followed by library categories that may stand in for it (best first).

Frames. THOR sizes are ``(x, y, z) = (width, height, depth)`` in the asset's own frame, whose
front faces ``+z``. holomj sizes are ``(x, y, z) = (depth, width, height)`` with the front facing
``+X`` (see :mod:`holomj.importers.frames`: the importer turns the asset by 90° so THOR ``+z``
is holomj ``+X``). So a THOR size ``(w, h, d)`` is the holomj size ``(d, w, h)``, in the object's
own frame (its yaw is applied separately). Checked on real houses: ``Bed_9`` (THOR
``[2.07, 1.35, 2.41]``) stands with its 2.41 m length between its headboard wall and the room.
"""

from __future__ import annotations

import json
import statistics
from dataclasses import dataclass
from functools import cache
from importlib import resources

from holomj.importers.frames import triple
from holomj.spec.categories import normalise_category

Size = tuple[float, float, float]


@dataclass(frozen=True)
class ThorAsset:
    """One THOR asset: its object type, holomj-frame size (depth, width, height) and flags."""

    asset_id: str
    type: str
    size: Size
    can_open: bool
    receptacle: bool


def holomj_size(thor_xyz: tuple[float, float, float] | list[float]) -> Size:
    """A THOR ``(width, height, depth)`` size as holomj ``(depth, width, height)``."""
    width, height, depth = (float(v) for v in thor_xyz)
    return (depth, width, height)


def _read(name: str) -> dict:
    return json.loads(resources.files("holomj.data").joinpath(name).read_text("utf-8"))


@cache
def thor_assets() -> dict[str, ThorAsset]:
    """The shipped asset table, by assetId."""
    table = _read("thor_assets.json")
    assets = {}
    for asset_id, entry in table.items():
        if asset_id.startswith("_"):
            continue
        thor_type, size, flags = entry
        assets[asset_id] = ThorAsset(
            asset_id=asset_id,
            type=thor_type,
            size=holomj_size(size),
            can_open="CanOpen" in flags,
            receptacle="Receptacle" in flags,
        )
    return assets


def thor_asset(asset_id: str) -> ThorAsset | None:
    """The THOR asset with this id (exact, then case-insensitive), or None."""
    table = thor_assets()
    found = table.get(asset_id)
    if found is None and asset_id:
        found = _by_lower().get(asset_id.lower())
    return found


@cache
def _by_lower() -> dict[str, ThorAsset]:
    return {k.lower(): v for k, v in sorted(thor_assets().items())}


@cache
def thor_type_table() -> dict[str, tuple[str, ...]]:
    """THOR type -> (holomj category, stand-in categories...)."""
    table = _read("thor_types.json")
    return {k: tuple(v) for k, v in table.items() if not k.startswith("_")}


@cache
def _types_by_key() -> dict[str, str]:
    return {normalise_category(k): k for k in thor_type_table()}


def thor_type(name: str) -> str | None:
    """The THOR type spelled ``name`` (case and separators ignored: ``"counter top"`` ->
    ``"CounterTop"``), or None."""
    return _types_by_key().get(normalise_category(name))


def thor_category(thor_type_name: str) -> str | None:
    """The holomj category of a THOR type (``"CounterTop"`` -> ``"kitchen_counter"``)."""
    entry = thor_type_table().get(thor_type_name)
    return entry[0] if entry else None


def thor_stand_ins(thor_type_name: str) -> tuple[str, ...]:
    """Library categories that may stand in for a THOR type, best first (its own aside)."""
    entry = thor_type_table().get(thor_type_name)
    return entry[1:] if entry else ()


@cache
def thor_type_opens(thor_type_name: str) -> bool:
    """Whether assets of a THOR type open (``CanOpen``: most of its assets do)."""
    flags = [a.can_open for a in thor_assets().values() if a.type == thor_type_name]
    return bool(flags) and 2 * sum(flags) >= len(flags)


@cache
def thor_type_size(thor_type_name: str) -> Size | None:
    """A typical size of a THOR type: the per-axis median over its assets (holomj frame)."""
    sizes = [a.size for a in thor_assets().values() if a.type == thor_type_name]
    if not sizes:
        return None
    return triple(round(statistics.median(s[i] for s in sizes), 4) for i in range(3))
