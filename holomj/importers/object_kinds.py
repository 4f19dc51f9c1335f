"""What an imported object is and how big it was authored: its holomj category, the
categories that may stand in for it, and its size with where that size came from.

* ProcTHOR objects (:func:`thor_object_kind`): the AI2-THOR asset table, else the THOR type
  spelled by the assetId or the id, with a typical size.
* Holodeck objects (:func:`holodeck_object_kind`): the name the house gives the object
  (``object_name``, or the id's first part) matched to a library category through the
  knowledge base's names (:mod:`holomj.importers.holodeck_hints`), and the authored size: the
  footprint (``vertices``) with the planned height, or a small object's listed extent, or the
  AI2-THOR table when its assetId is a THOR asset.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from holomj.importers.holodeck_hints import (
    HolodeckHints,
    KnownKind,
    base_name,
    category_for_name,
    scaled_to_extent,
)
from holomj.importers.jsonpath import Node
from holomj.importers.substitute import category_size
from holomj.importers.thor_assets import (
    thor_asset,
    thor_category,
    thor_stand_ins,
    thor_type,
    thor_type_opens,
    thor_type_size,
)
from holomj.library.store import AssetLibrary

_INSTANCE_SUFFIX = re.compile(r"-\d+$")  # Holodeck instance numbers: "sofa-0"
Size = tuple[float, float, float]


@dataclass(frozen=True)
class Kind:
    """What an object is: its holomj category, categories that may stand in for it, its
    source size (x = depth, y = width, z = height, own frame) with where that came from, and
    whether it opens (THOR's ``CanOpen``: an articulated stand-in is preferred)."""

    category: str
    stand_ins: tuple[str, ...] = ()
    size: tuple[float, float, float] | None = None
    size_source: str | None = None
    can_open: bool = False


_NOT_A_TYPE = {"small", "surface", "exterior", "object"}


def thor_object_kind(node: Node, raw_id: str, asset: str) -> Kind:
    """The object's kind.

    * Holodeck ``object_name`` (``"coffee table-0"`` -> ``"coffee table"``) names the category.
    * An assetId in the AI2-THOR table (:mod:`holomj.importers.thor_assets`) gives the THOR type,
      hence the category (``holomj/data/thor_types.json``), and the true size.
    * Otherwise the THOR type spelled by the assetId's leading words (``"Coffee_Table_3"`` ->
      ``CoffeeTable``), else by the id's first part (``"Sofa|2|1"`` -> ``Sofa``; Holodeck small
      objects ``"mug-0|table-0 (kitchen)"`` -> ``Mug``), with a typical size of the type.
    * Otherwise the id's first part when it is a word (never the number or ``small`` that start
      ProcTHOR 0.0.1 ids such as ``4|2|4`` and ``small|4|1``), else the assetId before ``_``.
    """
    thor = thor_asset(asset) if asset else None
    name = node.opt("object_name")
    if name is not None:
        text = _INSTANCE_SUFFIX.sub("", name.string()).strip()
        if thor is not None:
            return Kind(text, size=thor.size, size_source="thor", can_open=thor.can_open)
        return Kind(text)
    if thor is not None:
        return _thor_kind(thor.type, thor.size, "thor", thor.can_open)
    first = _INSTANCE_SUFFIX.sub("", raw_id.split("|", 1)[0]).strip()
    word = first if _is_word(first) else ""
    thor_name = _type_from_asset_id(asset) or (thor_type(word) if word else None)
    if thor_name is not None:
        size = category_size(thor_name) or category_size(thor_category(thor_name) or "")
        size = size or thor_type_size(thor_name)
        return _thor_kind(thor_name, size, "category" if size else None, thor_type_opens(thor_name))
    text = word or (asset.split("_", 1)[0] if asset else "") or "object"
    size = category_size(text)
    return Kind(text, size=size, size_source="category" if size else None)


def _thor_kind(
    thor_name: str, size: tuple[float, float, float] | None, source: str | None, opens: bool
) -> Kind:
    # The THOR type itself comes last: a library may file assets under THOR's names ("Chair").
    category = thor_category(thor_name) or thor_name
    return Kind(category, (*thor_stand_ins(thor_name), thor_name), size, source, opens)


def _is_word(text: str) -> bool:
    return any(c.isalpha() for c in text) and text.lower() not in _NOT_A_TYPE


def _type_from_asset_id(asset: str) -> str | None:
    """The THOR type spelled by the longest run of leading words of an assetId."""
    words = [w for w in re.split(r"[_\s]+", asset) if w]
    for end in range(len(words), 0, -1):
        found = thor_type("".join(words[:end]))
        if found is not None:
            return found
    return None


@dataclass(frozen=True)
class Authored:
    """Where a Holodeck object was authored: its footprint along its own axes (metres, if the
    house gives ``vertices``), the height of its centre (unity y), its room and whether it
    rests on a receptacle."""

    footprint: tuple[float, float] | None
    centre_height: float
    room: str | None
    child: bool
    above_support: float | None = None  # its centre above its receptacle's top (source)


def holodeck_object_kind(
    node: Node, raw_id: str, asset: str, hints: HolodeckHints, library: AssetLibrary,
    authored: Authored,
) -> Kind:  # fmt: skip
    """The kind of a Holodeck object (see the module notes). Its size source is ``thor``
    (the AI2-THOR table), ``footprint`` (vertices and the planned or authored height),
    ``extent`` (a small object's listed largest side) or ``category`` (a typical size)."""
    name_node = node.opt("object_name")
    name = base_name(name_node.string() if name_node is not None else raw_id)
    known = category_for_name(name, library.categories())
    category = known.category if known is not None else name
    thor = thor_asset(asset) if asset else None
    if thor is not None:
        stand_ins = (*thor_stand_ins(thor.type), thor.type)
        return Kind(category, stand_ins, thor.size, "thor", thor.can_open)
    size = _authored_size(name, raw_id, hints, library, authored, known)
    if size is None:
        typical = _typical_size(category, library, known)
        return Kind(category, size=typical, size_source="category" if typical else None)
    return Kind(category, size=size[0], size_source=size[1])


def _authored_size(
    name: str,
    raw_id: str,
    hints: HolodeckHints,
    library: AssetLibrary,
    authored: Authored,
    known: KnownKind | None,
) -> tuple[Size, str] | None:
    planned = hints.plan_size(authored.room, name)
    if authored.footprint is not None:
        depth, width = authored.footprint
        if planned is not None:
            height = planned[2]
        elif not authored.child and not hints.on_wall(authored.room, name):
            height = 2 * authored.centre_height  # standing on the floor: centre at half height
        else:
            typical = _typical_size(known.category if known else name, library, known)
            height = typical[2] if typical else min(depth, width)
        if height > 0:
            return (depth, width, height), "footprint"
    extent = hints.small_extent(raw_id)
    if extent is not None:
        typical = _typical_size(known.category if known else name, library, known) or planned
        if typical is not None:
            return scaled_to_extent(typical, extent), "extent"
        # Nothing says its shape: as wide as listed, as tall as its centre was above its
        # receptacle allows (a throw blanket is not a cube).
        above = authored.above_support
        height = min(max(2 * above, 0.02), extent) if above and above > 0 else extent / 2
        return (extent, extent, height), "extent"
    return None


def _typical_size(category: str, library: AssetLibrary, known: KnownKind | None) -> Size | None:
    """A typical size of ``category``: the size table, the knowledge base, else the first
    library asset of the category."""
    size = category_size(category) or (known.size if known is not None else None)
    if size is not None:
        return size
    assets = library.by_category(category)
    return assets[0].meta.size if assets else None
