"""The fast ranking path gives exactly the results of scoring every candidate exactly.

The reference below is the formula the retriever used before the index: every candidate's text
score as float64 row-wise products of the float32 embeddings, S from
:func:`size_discrepancy` per asset, M = (alpha + beta) T - gamma S, sorted by score then id.
The library is built to be hard: duplicated descriptions (exact ties, broken by id) and
clusters of vectors closer to each other than a float32 product can tell apart.
"""

from __future__ import annotations

import zlib
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pytest

from holomj.library.store import AssetLibrary, LibraryAsset
from holomj.retrieval.assets import VARIED_POOL, AssetRetriever
from holomj.retrieval.index import (
    approximate_text_scores,
    exact_text_scores,
    shortlist,
    size_discrepancies,
    text_error_bound,
)
from holomj.retrieval.scores import RetrievalWeights, ScoredAsset, asset_text, size_discrepancy
from holomj.spec.assets import AssetMeta

DIM = 48
CATEGORIES = ("sofa", "armchair", "dining_table", "desk", "floor_lamp", "bed")


class ClusterEncoder:
    """Deterministic vectors: ``"<base>#<k>"`` is ``<base>``'s vector nudged by ``k * 3e-8``
    along a fixed direction (below float32 resolution of the products), then normalised. An
    asset text's category words (before ``": "``) are left out, so queries hit clusters."""

    name = "cluster-test"
    dim = DIM

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        out = np.empty((len(texts), DIM), dtype=np.float32)
        for row, text in enumerate(texts):
            base, _, nudge = text.rsplit(": ", 1)[-1].partition("#")
            rng = np.random.default_rng(zlib.crc32(base.encode()))
            v = rng.normal(size=DIM)
            if nudge:
                v = v / np.linalg.norm(v) + 3e-8 * int(nudge) * np.ones(DIM) / np.sqrt(DIM)
            out[row] = v / np.linalg.norm(v)
        return out


def _library(root: Path, count: int, seed: int = 0) -> AssetLibrary:
    rng = np.random.default_rng(seed)
    template = AssetMeta.model_validate(
        {
            "id": "template",
            "category": "sofa",
            "size": [1.0, 1.0, 1.0],
            "visual": [{"mesh": "box.obj"}],
            "collision": [{"kind": "box", "size": [0.5, 0.5, 0.5], "volume_m3": 1.0}],
        }
    )
    assets = {}
    for k in range(count):
        category = CATEGORIES[k % len(CATEGORIES)]
        base = f"{category} style {int(rng.integers(6))}"
        # a third share one text exactly, a third differ by a sub-float32 nudge
        text = base if k % 3 == 0 else f"{base}#{int(rng.integers(1, 4))}"
        size = tuple(round(float(v), 2) for v in rng.uniform(0.4, 2.0, 3))
        placement = ["floor"] if k % 7 else ["floor", "wall"]
        meta = template.model_copy(
            update={
                "id": f"a{int(rng.integers(10**6)):06d}_{k}",
                "category": category,
                "description": text,
                "size": size,
                "placement": placement,
            }
        )
        assets[meta.id] = LibraryAsset(meta=meta, root=root / meta.id)
    return AssetLibrary(root, "index-test", assets)


def _reference(
    retriever: AssetRetriever,
    description: str,
    size: tuple[float, float, float] | None,
    placement: str,
    category: str | None,
) -> list[tuple[str, float, float, float]]:
    """Every candidate scored exactly, best first (id, score, text, size)."""
    encoder = retriever.encoder
    assets = [
        retriever.library.get(i)
        for i in retriever.library.ids()
        if i != "builtin:box" and placement in retriever.library.get(i).meta.placement
    ]
    if category is not None:
        assets = [a for a in assets if a.meta.category == category]
    texts = [asset_text(a) for a in assets]
    vectors = encoder.encode(texts).astype(np.float64)
    query = encoder.encode([description])[0].astype(np.float64)
    text = (vectors * query).sum(axis=1)
    sizes = np.array([0.0 if size is None else size_discrepancy(size, a.meta.size) for a in assets])
    w = retriever.weights
    score = (w.text + w.visual) * text - w.size * sizes
    rows = sorted(range(len(assets)), key=lambda k: (-score[k], assets[k].meta.id))
    return [(assets[k].meta.id, score[k], text[k], sizes[k]) for k in rows]


def _plain(picks: list[ScoredAsset]) -> list[tuple[str, float, float, float]]:
    return [(p.asset_id, p.score, p.text, p.size) for p in picks]


@pytest.fixture
def retriever(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> AssetRetriever:
    library = _library(tmp_path / "library", 1500)
    return AssetRetriever(library, encoder=ClusterEncoder())


QUERIES = [
    ("sofa style 2", (2.0, 0.9, 0.8), "floor", None),
    ("sofa style 2", (2.0, 0.9, 0.8), "floor", "sofa"),
    ("desk style 4#2", None, "floor", None),
    ("floor lamp style 1", (0.4, 0.4, 1.6), "floor", "floor_lamp"),
    ("bed style 5", (1.6, 2.1, 1.0), "wall", None),
    ("something else entirely", (1.0, 1.0, 1.0), "floor", None),
]


@pytest.mark.parametrize(("description", "size", "placement", "category"), QUERIES)
def test_rank_matches_exact_scoring_of_every_candidate(
    retriever: AssetRetriever,
    description: str,
    size: tuple[float, float, float] | None,
    placement: str,
    category: str | None,
) -> None:
    reference = _reference(retriever, description, size, placement, category)
    for limit in (1, 2, 5, 10, 40, len(reference) + 5):
        got = retriever.rank(
            description, size=size, placement=placement, category=category, limit=limit
        )
        assert _plain(got) == reference[:limit]  # same ids, order and bit-equal scores


@pytest.mark.parametrize(("description", "size", "placement", "category"), QUERIES)
def test_choose_matches_picks_from_the_full_ranking(
    retriever: AssetRetriever,
    description: str,
    size: tuple[float, float, float] | None,
    placement: str,
    category: str | None,
) -> None:
    reference = _reference(retriever, description, size, placement, category)
    for quantity, variance in ((1, "same"), (3, "same"), (2, "varied"), (6, "varied")):
        got = retriever.choose(
            description,
            quantity=quantity,
            variance=variance,
            rng=np.random.default_rng(7),
            size=size,
            placement=placement,
            category=category,
        )
        expected = _reference_pick(retriever, reference, quantity, variance)
        assert [p.asset_id for p in got] == expected


def _reference_pick(
    retriever: AssetRetriever, ranking: list, quantity: int, variance: str
) -> list[str]:
    """The picking rule of ``choose`` applied to a full ranking (the rule before the index)."""
    rng = np.random.default_rng(7)
    best = ranking[0][0]
    if variance == "same" or quantity == 1:
        return [best] * quantity
    kind = retriever.library.get(best).meta.category
    same = [r[0] for r in ranking if retriever.library.get(r[0]).meta.category == kind]
    pool = same[: 1 + max(quantity - 1, VARIED_POOL)]
    extra = min(quantity - 1, len(pool) - 1)
    picks = [best]
    if extra > 0:
        picks += [pool[int(k)] for k in rng.choice(np.arange(1, len(pool)), extra, False)]
    chosen = [picks[k % len(picks)] for k in range(quantity)]
    return [chosen[int(k)] for k in rng.permutation(quantity)]


def test_duplicates_tie_exactly_and_break_by_id(retriever: AssetRetriever) -> None:
    picks = retriever.rank("sofa style 3", category="sofa", limit=200)
    by_text: dict[str, list[ScoredAsset]] = {}
    for pick in picks:
        by_text.setdefault(retriever.library.get(pick.asset_id).meta.description, []).append(pick)
    ties = [group for group in by_text.values() if len(group) > 1]
    assert ties
    for group in ties:
        assert len({p.text for p in group}) == 1
        same_score = [p for p in group if p.size == group[0].size]
        assert [p.asset_id for p in same_score] == sorted(p.asset_id for p in same_score)


def test_size_discrepancies_are_bit_equal_to_the_scalar_formula() -> None:
    rng = np.random.default_rng(3)
    sizes = rng.uniform(0.01, 4.0, (500, 3))
    requested = (1.3, 0.7, 2.2)
    vector = size_discrepancies(requested, sizes, 1.5)
    scalar = [size_discrepancy(requested, tuple(s)) for s in sizes]
    assert vector.tolist() == scalar


def test_shortlist_keeps_every_true_best_row() -> None:
    rng = np.random.default_rng(11)
    matrix = rng.normal(size=(20000, 384)).astype(np.float32)
    matrix /= np.linalg.norm(matrix, axis=1, keepdims=True)
    matrix[5000:5100] = matrix[42] + np.float32(1e-7)  # a block of near-duplicates
    query = matrix[42].copy()
    rows = np.arange(matrix.shape[0])
    exact = exact_text_scores(matrix, query, rows)
    approximate = approximate_text_scores(matrix, query, rows)
    error = text_error_bound(384, 1.0001, query)
    assert np.abs(approximate - exact).max() <= error
    for limit in (1, 10, 150):
        kept = set(shortlist(approximate, limit, error).tolist())
        best = np.lexsort((rows, -exact))[:limit]
        assert set(best.tolist()) <= kept
        assert len(kept) < 1000


def test_ranking_a_large_index_is_fast(tmp_path: Path) -> None:
    """20,000 assets (an eighth of the benchmark's scale, same path): a query without a
    category, its embedding cached, ranks in well under the 50 ms the benchmark asks at
    100,000 (scripts/bench_retrieval.py measures that)."""
    import time

    library = _library(tmp_path / "library", 20000, seed=1)
    retriever = AssetRetriever(library, encoder=ClusterEncoder(), weights=RetrievalWeights())
    retriever.rank("sofa style 1", size=(2.0, 0.9, 0.8), limit=10)  # builds the index
    start = time.perf_counter()
    for _ in range(5):
        retriever.rank("sofa style 1", size=(2.0, 0.9, 0.8), limit=10)
    assert (time.perf_counter() - start) / 5 < 0.05


def test_near_ties_below_float32_resolution(tmp_path: Path) -> None:
    """300 assets whose scores differ by less than a float32 product can resolve: the
    shortlist's margin keeps every one of the exact best (ranking them by the float32 scores
    alone would not)."""
    template = AssetMeta.model_validate(
        {
            "id": "template",
            "category": "sofa",
            "size": [1.0, 1.0, 1.0],
            "visual": [{"mesh": "box.obj"}],
            "collision": [{"kind": "box", "size": [0.5, 0.5, 0.5], "volume_m3": 1.0}],
        }
    )
    root = tmp_path / "library"
    assets = {}
    for k in range(300):
        meta = template.model_copy(
            update={"id": f"s{(k * 7919) % 300:03d}", "description": f"sofa style 0#{k + 1}"}
        )
        assets[meta.id] = LibraryAsset(meta=meta, root=root / meta.id)
    retriever = AssetRetriever(AssetLibrary(root, "ties", assets), encoder=ClusterEncoder())
    reference = _reference(retriever, "sofa style 0", (1.0, 1.0, 1.0), "floor", None)
    assert len({r[1] for r in reference}) > 20  # many distinct, nearly equal scores
    for limit in (1, 5, 50, 150):
        got = retriever.rank("sofa style 0", size=(1.0, 1.0, 1.0), limit=limit)
        assert _plain(got) == reference[:limit]
