"""The embeddings a retriever scores with, computed once and cached: the asset texts' matrix
(on disk, :mod:`holomj.retrieval.cache`), query embeddings, category-name embeddings, a few
whole-matrix products, and the assets' thumbnail embeddings for the visual term."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from holomj.library.store import LibraryAsset
from holomj.retrieval.cache import EmbeddingCache, cache_file, content_key
from holomj.retrieval.index import FULL_PRODUCT_SHARE, approximate_text_scores
from holomj.retrieval.scores import asset_text
from holomj.retrieval.text import TextEncoder
from holomj.retrieval.visual import VisualScorer, best_view_score

KEPT_PRODUCTS = 8
"""Descriptions whose scores against the whole embedding matrix a retriever keeps."""


class AssetVectors:
    """The embeddings of one library's assets and of the descriptions asked of it.

    ``note`` receives what the caller should report (a cache problem, missing thumbnails).
    The text encoder is the given one, else the default one, loaded on first use.
    """

    def __init__(
        self,
        root: Path,
        assets: Sequence[LibraryAsset],
        *,
        encoder: TextEncoder | None,
        visual: VisualScorer | None,
        note: Callable[[str], None],
    ) -> None:
        self.root = root
        self.note = note
        self.visual = visual
        self.max_norm = 0.0
        self._assets = list(assets)
        self._encoder = encoder
        self._matrix: np.ndarray | None = None
        self._views: list[np.ndarray] | None = None
        self._text_queries: dict[str, np.ndarray] = {}
        self._visual_queries: dict[str, np.ndarray] = {}
        self._products: dict[str, np.ndarray] = {}
        self._category_vectors: dict[str, np.ndarray] = {}

    @property
    def encoder(self) -> TextEncoder:
        """The text encoder (the default one is loaded on first use)."""
        if self._encoder is None:
            from holomj.retrieval.text import text_encoder

            self._encoder = text_encoder()
        return self._encoder

    def text_of(self, asset: LibraryAsset) -> np.ndarray:
        """The embedding of one asset's text (an asset made after the matrix was built)."""
        return self.encoder.encode([asset_text(asset)])[0]

    def approximate(self, description: str, rows: np.ndarray) -> np.ndarray:
        """Approximate T of ``rows``; a product with the whole matrix is kept for the last
        :data:`KEPT_PRODUCTS` descriptions (``choose`` ranks twice, instances rank again)."""
        matrix, query = self.text_matrix(), self.text_query(description)
        if rows.size <= FULL_PRODUCT_SHARE * matrix.shape[0]:
            return approximate_text_scores(matrix, query, rows)
        if description not in self._products:
            if len(self._products) >= KEPT_PRODUCTS:
                del self._products[next(iter(self._products))]
            self._products[description] = approximate_text_scores(
                matrix, query, np.arange(matrix.shape[0])
            )
        return self._products[description][rows]

    def text_query(self, description: str) -> np.ndarray:
        """The text embedding of a description (computed once)."""
        if description not in self._text_queries:
            self._text_queries[description] = self.encoder.encode([description])[0]
        return self._text_queries[description]

    def text_matrix(self) -> np.ndarray:
        """The asset texts' embeddings, one row per asset (from the cache, else computed)."""
        if self._matrix is None:
            encoder = self.encoder
            texts = [asset_text(a) for a in self._assets]
            keys = [content_key(encoder.name, t) for t in texts]
            cache = self._cache(encoder.name)
            matrix = cache.fetch(keys, lambda idx: encoder.encode([texts[i] for i in idx]))
            for note in cache.notes:
                self.note(note)
            self._matrix = np.ascontiguousarray(matrix, dtype=np.float32)
            if matrix.size:
                self.max_norm = float(np.sqrt((matrix.astype(np.float64) ** 2).sum(1).max()))
        return self._matrix

    def _cache(self, model_name: str) -> EmbeddingCache:
        return EmbeddingCache(cache_file(self.root, model_name))

    def category_vector(self, category: str) -> np.ndarray:
        """The text embedding of a category name, as words (computed once)."""
        words = " ".join(category.replace("_", " ").replace("-", " ").split()).lower()
        if words not in self._category_vectors:
            self._category_vectors[words] = self.encoder.encode([words])[0].astype(np.float64)
        return self._category_vectors[words]

    def visual_terms(
        self, description: str, rows: np.ndarray, *, enabled: bool = True
    ) -> list[float | None] | None:
        """V per candidate (None for one without thumbnails), or None when V is left out."""
        if self.visual is None or not enabled:
            return None
        views = self.thumbnail_vectors()
        if not any(views[r].shape[0] for r in rows):
            self.note(
                "no candidate asset has thumbnails: the visual term V is left out and its "
                "weight goes to the text term T"
            )
            return None
        if description not in self._visual_queries:
            self._visual_queries[description] = self.visual.encode_texts([description])[0]
        query = self._visual_queries[description]
        bare = sum(1 for r in rows if views[r].shape[0] == 0)
        if bare:
            self.note(
                "assets without thumbnails get the median visual score of the others "
                f"(e.g. {bare} candidate(s) for {description!r})"
            )
        return [best_view_score(query, views[r]) if views[r].shape[0] else None for r in rows]

    def thumbnail_vectors(self) -> list[np.ndarray]:
        """Each asset's thumbnail embeddings (no rows: no thumbnails), computed once."""
        if self._views is not None:
            return self._views
        scorer = self.visual
        assert scorer is not None
        paths: list[Path] = []
        owners: list[int] = []
        for k, asset in enumerate(self._assets):
            for rel in asset.meta.thumbnails:
                path = asset.path(rel)
                if path.is_file():
                    paths.append(path)
                    owners.append(k)
                else:
                    self.note(f"thumbnail {rel!r} of asset {asset.meta.id!r} is missing")
        keys = [content_key(scorer.name, p.read_bytes()) for p in paths]
        cache = self._cache(scorer.name)
        matrix = cache.fetch(keys, lambda idx: scorer.encode_images([paths[i] for i in idx]))
        for note in cache.notes:
            self.note(note)
        dim = matrix.shape[1] if matrix.size else 0
        views = [np.zeros((0, dim), np.float32) for _ in self._assets]
        for k in range(len(self._assets)):
            mine = [row for row, owner in enumerate(owners) if owner == k]
            if mine:
                views[k] = matrix[mine]
        self._views = views
        return views
