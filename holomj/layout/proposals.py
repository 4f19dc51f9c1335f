"""Which small objects go on which receptacle, and how many: proposals for spawn-and-drop.

A receptacle's capacity grows with the total area of its support surfaces: one object per
``AREA_PER_OBJECT_M2`` (0.06 m², about a plate with room around it), at most
``max_per_receptacle`` (15). The objects' categories are drawn, with the caller's generator,
from the receptacle category's weighted list in the catalogue
(``holomj/data/small_objects_on_receptacles.json`` by default). A catalogue key
``"<room type>:<receptacle category>"`` overrides the plain key in rooms of that type.
Receptacles with no surfaces or no catalogue entry get no proposal.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from holomj.errors import SpecError
from holomj.spec.assets import AssetMeta
from holomj.spec.categories import SHARED_RECEPTACLES_FILE as CATALOGUE_FILE
from holomj.spec.categories import ReceptacleTable, receptacle_file_table, receptacle_key
from holomj.spec.categories import parse_receptacle_table as parse_catalogue

AREA_PER_OBJECT_M2 = 0.06
MAX_PER_RECEPTACLE = 15

Catalogue = Mapping[str, Sequence[tuple[str, float]]]


@dataclass(frozen=True)
class ReceptacleProposal:
    """Put ``count`` objects of ``category`` on the receptacle ``receptacle_id``."""

    receptacle_id: str
    category: str
    count: int


def _default_catalogue() -> ReceptacleTable:
    return receptacle_file_table(CATALOGUE_FILE)


def default_catalogue() -> dict[str, list[tuple[str, float]]]:
    """The shipped catalogue: receptacle category -> [(small object category, weight)]."""
    return {key: list(items) for key, items in _default_catalogue().items()}


def capacity(meta: AssetMeta, max_per_receptacle: int = MAX_PER_RECEPTACLE) -> int:
    """How many small objects a receptacle holds: its surface area / 0.06 m², at most the cap."""
    area = sum(surface.area_m2 for surface in meta.surfaces)
    return min(max_per_receptacle, math.floor(area / AREA_PER_OBJECT_M2 + 1e-9))


def propose_small_objects(
    receptacles: Sequence[tuple[str, AssetMeta, str]],
    catalogue: Catalogue | None,
    rng: np.random.Generator,
    *,
    max_per_receptacle: int = MAX_PER_RECEPTACLE,
) -> list[ReceptacleProposal]:
    """Proposals for every receptacle given as (object id, asset metadata, room type).

    ``catalogue`` None means the shipped one. Counts per category are one multinomial draw of
    the receptacle's capacity over the catalogue weights; proposals come in receptacle order,
    then catalogue order, with zero counts left out.
    """
    if max_per_receptacle < 0:
        raise SpecError(f"max_per_receptacle is {max_per_receptacle}", fix="use 0 or more")
    table = _default_catalogue() if catalogue is None else parse_catalogue(dict(catalogue))
    proposals: list[ReceptacleProposal] = []
    for object_id, meta, room_type in receptacles:
        items = table.get(receptacle_key(f"{room_type}:{meta.category}")) or table.get(
            receptacle_key(meta.category)
        )
        if not items:
            continue
        weights = np.array([w for _, w in items], dtype=float)
        if weights.sum() <= 0:
            continue
        n = capacity(meta, max_per_receptacle)
        if n == 0:
            continue
        counts = rng.multinomial(n, weights / weights.sum())
        merged: dict[str, int] = {}
        for (category, _), count in zip(items, counts):
            if count > 0:
                merged[category] = merged.get(category, 0) + int(count)
        proposals.extend(
            ReceptacleProposal(object_id, category, count) for category, count in merged.items()
        )
    return proposals
