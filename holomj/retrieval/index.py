"""The arrays a retriever ranks over, built once per library view, and the fast scoring steps.

:class:`AssetIndex` holds, per asset (in the retriever's order): its id's rank among the
sorted ids (ties in score are broken by id), its category (raw and normalised), its size and
which placements it allows, so that choosing candidates (a category, its aliases, a placement)
is an array lookup instead of a loop over assets.

Text scores are exact where they decide anything: :func:`exact_text_scores` is the reference
formula (float64 products of the float32 embeddings, summed per row), and
:func:`approximate_text_scores` (one float32 matrix product) only narrows the candidates
down to a shortlist that provably holds the best ones (:func:`shortlist`): within
:func:`text_error_bound` of exact for every row, so ranking the shortlist exactly gives the
same results, scores and ties as ranking every candidate exactly.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from holomj.library.store import LibraryAsset
from holomj.spec.categories import normalise_category

FULL_PRODUCT_SHARE = 0.25
"""Above this share of the index, the approximate scores come from one product with the whole
matrix (no gather of rows) and are then indexed."""


@dataclass(frozen=True)
class AssetIndex:
    """Per-asset arrays of one retriever's assets (row ``k`` is its ``k``-th asset)."""

    ids: tuple[str, ...]
    id_rank: np.ndarray  # (n,) position of each id among the sorted ids
    categories: np.ndarray  # (n,) object array of the raw category names
    category_codes: np.ndarray  # (n,) int: index of the raw category in ``category_names``
    category_names: dict[str, int]  # raw category name -> code
    by_category: dict[str, np.ndarray]  # normalised category -> sorted rows
    sizes: np.ndarray  # (n, 3) float64, the assets' (x, y, z)
    placements: dict[str, np.ndarray]  # placement -> (n,) bool
    own: np.ndarray  # (n,) bool: not made on demand

    @classmethod
    def build(cls, assets: Sequence[LibraryAsset], on_demand: frozenset[str]) -> AssetIndex:
        """The index of ``assets`` (``on_demand``: the sources of assets made on demand)."""
        n = len(assets)
        ids = tuple(a.meta.id for a in assets)
        order = sorted(range(n), key=ids.__getitem__)
        id_rank = np.empty(n, dtype=np.int64)
        id_rank[order] = np.arange(n, dtype=np.int64)
        categories = np.array([a.meta.category for a in assets], dtype=object)
        names: dict[str, int] = {}
        codes = np.array(
            [names.setdefault(a.meta.category, len(names)) for a in assets], dtype=np.int64
        )
        grouped: dict[str, list[int]] = {}
        placements: dict[str, np.ndarray] = {}
        for k, asset in enumerate(assets):
            grouped.setdefault(normalise_category(asset.meta.category), []).append(k)
            for placement in asset.meta.placement:
                placements.setdefault(placement, np.zeros(n, dtype=bool))[k] = True
        sizes = np.array([a.meta.size for a in assets], dtype=np.float64).reshape(n, 3)
        own = np.array([a.meta.source not in on_demand for a in assets], dtype=bool)
        return cls(
            ids=ids,
            id_rank=id_rank,
            categories=categories,
            category_codes=codes,
            category_names=names,
            by_category={k: np.array(v, dtype=np.int64) for k, v in grouped.items()},
            sizes=sizes,
            placements=placements,
            own=own,
        )

    def placed(self, placement: str, own_only: bool = False) -> np.ndarray:
        """Mask of the rows allowing ``placement`` (and not made on demand, with
        ``own_only``)."""
        mask = self.placements.get(placement)
        if mask is None:
            return np.zeros(len(self.ids), dtype=bool)
        return mask & self.own if own_only else mask

    def of_categories(self, mask: np.ndarray, keys: set[str]) -> np.ndarray:
        """The rows in ``mask`` whose normalised category is one of ``keys``, in row order."""
        found = [self.by_category[k] for k in sorted(keys) if k in self.by_category]
        if not found:
            return np.zeros(0, dtype=np.int64)
        rows = found[0] if len(found) == 1 else np.sort(np.concatenate(found))
        return rows[mask[rows]]

    def of_category_name(self, rows: np.ndarray, category: str) -> np.ndarray:
        """The ``rows`` whose raw category is exactly ``category``."""
        code = self.category_names.get(category)
        if code is None:
            return np.zeros(0, dtype=np.int64)
        return rows[self.category_codes[rows] == code]

    def order(self, rows: np.ndarray, scores: np.ndarray) -> np.ndarray:
        """Positions into ``rows`` best first: by score, ties by asset id."""
        return np.lexsort((self.id_rank[rows], -scores))


def size_discrepancies(
    requested: tuple[float, float, float], sizes: np.ndarray, cap: float
) -> np.ndarray:
    """S (metres) of every row of ``sizes`` (x, y, z) against ``requested`` (width, depth,
    height): the same arithmetic, in the same order, as
    :func:`holomj.retrieval.assets.size_discrepancy`, so the values are bit-equal."""
    width, depth, height = requested
    x, y, z = sizes[:, 0], sizes[:, 1], sizes[:, 2]
    dz = np.minimum(np.abs(z - height), cap)
    straight = np.minimum(np.abs(y - width), cap) + np.minimum(np.abs(x - depth), cap)
    turned = np.minimum(np.abs(x - width), cap) + np.minimum(np.abs(y - depth), cap)
    return (np.minimum(straight, turned) + dz) / 3.0


def exact_text_scores(matrix: np.ndarray, query: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """T of ``rows``: float64 row-wise products and sums (equal rows give bit-equal scores,
    whatever their position; a BLAS product may not)."""
    vectors = matrix[rows].astype(np.float64)
    return (vectors * query.astype(np.float64)).sum(axis=1)


def approximate_text_scores(matrix: np.ndarray, query: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """T of ``rows`` from one float32 product (within :func:`text_error_bound` of exact)."""
    q = np.asarray(query, dtype=np.float32)
    if rows.size > FULL_PRODUCT_SHARE * matrix.shape[0]:
        return (matrix @ q)[rows].astype(np.float64)
    return (matrix[rows] @ q).astype(np.float64)


def text_error_bound(dim: int, max_row_norm: float, query: np.ndarray) -> float:
    """A bound on |approximate - exact| text score: a float32 dot product of length ``dim``
    errs by at most ``dim * 2**-24 * sum |v_i q_i|`` (Higham), and ``sum |v_i q_i| <= |v| |q|``;
    twice that covers the rounding of the products and of the result."""
    q_norm = float(np.linalg.norm(np.asarray(query, dtype=np.float64)))
    return dim * 2.0**-23 * max_row_norm * q_norm + 1e-12


def shortlist(approximate: np.ndarray, limit: int, error: float) -> np.ndarray:
    """Positions of the scores that may be among the ``limit`` best when every score is off by
    at most ``error``: the ``limit``-th best exact score is within ``error`` of the
    ``limit``-th best approximate one, so every row at least that good is kept by a margin of
    ``2 * error``."""
    if limit >= approximate.size:
        return np.arange(approximate.size)
    kth = -np.partition(-approximate, limit - 1)[limit - 1]
    return np.flatnonzero(approximate >= kth - 2.0 * error)
