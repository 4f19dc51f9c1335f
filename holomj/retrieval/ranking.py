"""Ranking library assets for object descriptions: Holodeck's score M = α·V + β·T − γ·S.

- **V** (visual): CLIP cosine between ``"a 3D model of <description>"`` and the asset's
  thumbnails, the best view counting (:mod:`holomj.retrieval.visual`). Left out, with a note,
  when no CLIP weights are configured or no candidate has thumbnails: T then carries V's
  weight too (M = (α + β)·T − γ·S), because both measure how well the asset fits the
  description and Holodeck's balance of relevance against size rests on α. Taken literally,
  β·T − γ·S lets the size term decide the category: on the labelled set of the tests, top-1
  category accuracy drops from 0.91 to 0.72. A candidate without thumbnails among others that
  have them gets the median V of those (neutral).
- **T** (text): sentence-embedding cosine between the description and the asset's text,
  ``"<category words>: <asset description>"``.
- **S** (size, metres): the mean absolute difference between the requested and the asset's
  extents, height against height and the footprint under the better of the two quarter turns
  (a 2 x 1 m bed matches a 1 x 2 m request), each difference capped at
  :data:`SIZE_CAP_M` so one absurd extent cannot swamp the other terms. 0 without a size.

Defaults α = 100, β = 1, γ = 10 as in Holodeck. Candidates are the assets whose placement
flags include the requested placement (``builtin:box`` never competes). A category hint
restricts them to that category when the library has it, else to its aliases
(``category_facts.json``); with neither, everything is scored and a note says so.
Ranking is by score, ties by asset id, so results are deterministic.

Embeddings of asset texts and thumbnails are cached in ``LIB/.cache/retrieval/``
(:mod:`holomj.retrieval.cache`); query embeddings are cached in memory per retriever.
"""

from __future__ import annotations

from typing import TypedDict

import numpy as np

from holomj.errors import InputError
from holomj.library.store import (
    BUILTIN_BOX,
    AssetLibrary,
    category_aliases,
    normalise_category,
)
from holomj.retrieval.index import (
    AssetIndex,
    exact_text_scores,
    shortlist,
    size_discrepancies,
    text_error_bound,
)
from holomj.retrieval.scores import (
    DEFAULT_WEIGHTS,
    SIZE_CAP_M,
    RetrievalWeights,
    ScoredAsset,
    check_placement,
    check_size,
)
from holomj.retrieval.text import TextEncoder
from holomj.retrieval.vectors import AssetVectors
from holomj.retrieval.visual import VisualScorer

ON_DEMAND_SOURCES = frozenset({"holomj synthesised", "holomj proxy"})
NO_CLIP_NOTE = (
    "CLIP weights not configured: the visual term V is left out and its weight goes to the "
    "text term T (set HOLOMJ_CLIP_WEIGHTS to a local open_clip checkpoint to use V)"
)


class RankerOptions(TypedDict, total=False):
    """The options of :class:`AssetRanker` (and of the retrievers built on it)."""

    encoder: TextEncoder | None
    visual: VisualScorer | None
    weights: RetrievalWeights


class AssetRanker:
    """Ranks a library's assets for object descriptions.

    The per-asset arrays (:class:`~holomj.retrieval.index.AssetIndex`) and the text embedding
    matrix are built once, on first use; a query embedding is computed once per description.
    Without the visual term, the best ``limit`` candidates are found from one float32 matrix
    product and then scored exactly (:mod:`holomj.retrieval.index`): the same results as
    scoring every candidate exactly, at a fraction of the cost on a large library.
    """

    def __init__(
        self,
        library: AssetLibrary,
        *,
        encoder: TextEncoder | None = None,
        visual: VisualScorer | None = None,
        weights: RetrievalWeights = DEFAULT_WEIGHTS,
    ) -> None:
        self.library = library
        self.weights = weights
        self.notes: list[str] = []
        self._assets = [library.get(i) for i in library.ids() if i != BUILTIN_BOX]
        self._index_of = {a.meta.id: k for k, a in enumerate(self._assets)}
        self._table: AssetIndex | None = None
        self.vectors = AssetVectors(
            library.root, self._assets, encoder=encoder, visual=visual, note=self._note
        )
        if visual is None:
            self._note(NO_CLIP_NOTE)

    @property
    def encoder(self) -> TextEncoder:
        """The text encoder (the default one is loaded on first use)."""
        return self.vectors.encoder

    @property
    def index(self) -> AssetIndex:
        """The per-asset arrays (built on first use)."""
        if self._table is None:
            self._table = AssetIndex.build(self._assets, ON_DEMAND_SOURCES)
        return self._table

    def _note(self, note: str) -> None:
        if note not in self.notes:
            self.notes.append(note)

    def rank(
        self,
        description: str,
        *,
        size: tuple[float, float, float] | None = None,
        placement: str = "floor",
        category: str | None = None,
        limit: int = 10,
    ) -> list[ScoredAsset]:
        """The ``limit`` best candidates for ``description``, best first.

        ``size`` is (width, depth, height) in metres (a plan object's), ``placement`` one of
        floor, wall, object (on a receptacle) or ceiling, ``category`` the planner's hint.
        """
        if limit < 1:
            raise InputError(f"limit must be at least 1, got {limit}", where="rank")
        rows = self._candidates(description, placement, category)
        return self._top(description, size, rows, limit)

    def _of_category(self, placed: np.ndarray, category: str) -> np.ndarray:
        """Rows of ``placed`` of ``category``, else of its stand-ins (``category_facts.json``)."""
        key = normalise_category(category)
        exact = self.index.of_categories(placed, {key})
        if exact.size:
            return exact
        aliases = {normalise_category(c) for c in category_aliases().get(key, [])}
        return self.index.of_categories(placed, aliases)

    def _candidates(self, description: str, placement: str, category: str | None) -> np.ndarray:
        check_placement(placement, description)
        placed = self.index.placed(placement)
        if not placed.any():
            raise InputError(
                f"no {placement} asset in library {self.library.name!r} for {description!r}",
                where=str(self.library.root),
                fix="import one with 'holomj assets import' or use another library",
            )
        if category is None:
            return np.flatnonzero(placed)
        rows = self._of_category(placed, category)
        if rows.size:
            return rows
        self._note(
            f"no {placement} asset of category {category!r} (or its aliases) in library "
            f"{self.library.name!r}: every {placement} asset was scored for {description!r}"
        )
        return np.flatnonzero(placed)

    def _top(
        self,
        description: str,
        size: tuple[float, float, float] | None,
        rows: np.ndarray,
        limit: int | None,
    ) -> list[ScoredAsset]:
        """The ``limit`` best of ``rows`` (None: all), best first, ties by asset id."""
        rows = np.asarray(rows, dtype=np.int64)
        if size is None:
            sizes = np.zeros(rows.size)
        else:
            requested = check_size(size, description)
            sizes = size_discrepancies(requested, self.index.sizes[rows], SIZE_CAP_M)
        w = self.weights
        visual = self.vectors.visual_terms(description, rows, enabled=w.visual != 0.0)
        text_weight = w.text if visual is not None else w.text + w.visual
        matrix = self.vectors.text_matrix()
        query = self.vectors.text_query(description)
        if visual is None and limit is not None and limit < rows.size:
            approximate = text_weight * self.vectors.approximate(description, rows)
            error = abs(text_weight) * text_error_bound(
                matrix.shape[1], self.vectors.max_norm, query
            )
            keep = shortlist(approximate - w.size * sizes, limit, error)
            rows, sizes = rows[keep], sizes[keep]
        text = exact_text_scores(matrix, query, rows)
        score = text_weight * text - w.size * sizes
        if visual is not None:
            known = np.array([v is not None for v in visual])
            values = np.array([v if v is not None else np.nan for v in visual], dtype=np.float64)
            neutral = float(np.median(values[known]))
            score = score + w.visual * np.where(known, values, neutral)
        order = self.index.order(rows, score)
        if limit is not None:
            order = order[:limit]
        return [
            ScoredAsset(
                asset_id=self.index.ids[int(rows[k])],
                category=str(self.index.categories[int(rows[k])]),
                score=float(score[k]),
                visual=None if visual is None else visual[k],
                text=float(text[k]),
                size=float(sizes[k]),
            )
            for k in order
        ]
