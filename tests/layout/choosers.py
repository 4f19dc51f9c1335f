"""A retrieval stand-in for layout tests: picks by category hint only, so layout tests do not
depend on the text model (the real retriever is tested in tests/retrieval and end to end)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from holomj.errors import InputError
from holomj.library.store import AssetLibrary


@dataclass(frozen=True)
class CategoryPick:
    asset_id: str
    category: str


class CategoryChooser:
    """The first asset (by id) of the hinted category with the wanted placement."""

    def __init__(self, library: AssetLibrary) -> None:
        self.library = library
        self.calls: list[tuple[str, str]] = []

    def choose(
        self,
        description: str,
        *,
        quantity: int,
        variance: str,
        rng: np.random.Generator,
        size=None,
        placement: str = "floor",
        category: str | None = None,
    ) -> list[CategoryPick]:
        self.calls.append((description, placement))
        assets = [
            a for a in self.library.by_category(category or "") if placement in a.meta.placement
        ]
        if not assets:
            raise InputError(f"no {placement} asset for {description!r}", where="test chooser")
        assets.sort(key=lambda a: a.meta.id)
        picks = []
        for k in range(quantity):
            asset = assets[k % len(assets)] if variance == "varied" else assets[0]
            picks.append(CategoryPick(asset.meta.id, asset.meta.category))
        return picks
