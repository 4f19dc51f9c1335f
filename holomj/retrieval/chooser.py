"""What the stages that place assets need of retrieval: something that chooses one asset per
instance of a planned object (:class:`holomj.retrieval.assets.AssetRetriever` is one; tests pass
their own)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

import numpy as np


class Pick(Protocol):
    """One retrieved asset (what :class:`holomj.retrieval.scores.ScoredAsset` offers)."""

    @property
    def asset_id(self) -> str:
        """The asset chosen."""
        ...


class AssetChooser(Protocol):
    """Chooses one asset per instance of a planned object."""

    def choose(
        self,
        description: str,
        *,
        quantity: int,
        variance: str,
        rng: np.random.Generator,
        size: tuple[float, float, float] | None = None,
        placement: str = "floor",
        category: str | None = None,
    ) -> Sequence[Pick]:
        """One pick per instance."""
        ...
