"""The embedding cache: refreshed when assets change, atomic, and harmless when unwritable."""

from __future__ import annotations

import numpy as np
import pytest

from holomj.retrieval.assets import AssetRetriever
from holomj.retrieval.cache import EmbeddingCache, cache_file, content_key
from holomj.retrieval.scores import asset_text
from tests.retrieval.conftest import AssetSpec, CountingEncoder

SOFA = AssetSpec("sofa_a", "sofa", "a grey three-seat sofa", (0.9, 2.0, 0.8))
BED = AssetSpec("bed_a", "bed", "a double bed with an oak frame", (2.1, 1.6, 1.0))
LAMP = AssetSpec("lamp_a", "floor_lamp", "a chrome floor lamp", (0.4, 0.4, 1.6))
DESK = AssetSpec("desk_a", "desk", "a walnut writing desk", (0.6, 1.2, 0.75))


def cached_keys(library, encoder) -> set[str]:
    with np.load(cache_file(library.root, encoder.name)) as data:
        assert data["vectors"].shape == (len(data["keys"]), encoder.dim)
        return {str(k) for k in data["keys"]}


def asset_keys(library, encoder) -> set[str]:
    return {
        content_key(encoder.name, asset_text(library.get(i)))
        for i in library.ids()
        if i != "builtin:box"
    }


def embedded_assets(encoder: CountingEncoder, query: str) -> list[str]:
    """Texts the encoder embedded for assets (everything but the query)."""
    return [t for t in encoder.seen if t != query]


def test_cache_is_refreshed_when_assets_are_added_changed_removed(
    library_factory, counting_encoder
):
    query = "a sofa"
    library = library_factory([SOFA, BED, LAMP])
    AssetRetriever(library, encoder=counting_encoder).rank(query)
    assert len(embedded_assets(counting_encoder, query)) == 3
    assert cached_keys(library, counting_encoder) == asset_keys(library, counting_encoder)

    counting_encoder.seen.clear()  # unchanged library: nothing embedded again
    ranked = AssetRetriever(library, encoder=counting_encoder).rank(query)
    assert embedded_assets(counting_encoder, query) == []
    assert ranked[0].asset_id == "sofa_a"

    counting_encoder.seen.clear()  # an asset added: only it is embedded
    library = library_factory([SOFA, BED, LAMP, DESK])
    AssetRetriever(library, encoder=counting_encoder).rank(query)
    assert embedded_assets(counting_encoder, query) == [asset_text(library.get("desk_a"))]
    assert cached_keys(library, counting_encoder) == asset_keys(library, counting_encoder)

    counting_encoder.seen.clear()  # a description changed: re-embedded, the old vector dropped
    old_keys = cached_keys(library, counting_encoder)
    changed = AssetSpec("bed_a", "bed", "a single bed with a metal frame", BED.size)
    library = library_factory([SOFA, changed, LAMP, DESK])
    ranked = AssetRetriever(library, encoder=counting_encoder).rank("a metal single bed")
    assert ranked[0].asset_id == "bed_a"
    assert embedded_assets(counting_encoder, "a metal single bed") == [
        asset_text(library.get("bed_a"))
    ]
    assert asset_text(library.get("bed_a")).endswith(": a single bed with a metal frame")
    keys = cached_keys(library, counting_encoder)
    assert keys == asset_keys(library, counting_encoder)
    assert len(keys - old_keys) == 1 and len(old_keys - keys) == 1

    counting_encoder.seen.clear()  # an asset removed: nothing embedded, its vector dropped
    library = library_factory([SOFA, changed, DESK])
    AssetRetriever(library, encoder=counting_encoder).rank(query)
    assert embedded_assets(counting_encoder, query) == []
    assert cached_keys(library, counting_encoder) == asset_keys(library, counting_encoder)
    assert len(cached_keys(library, counting_encoder)) == 3
    leftovers = [p.name for p in cache_file(library.root, "x").parent.iterdir()]
    assert leftovers == [cache_file(library.root, counting_encoder.name).name]  # no temp files


def test_query_embeddings_are_cached_per_retriever(library_factory, counting_encoder):
    retriever = AssetRetriever(library_factory([SOFA, BED]), encoder=counting_encoder)
    for _ in range(3):
        retriever.rank("a comfy sofa")
        retriever.choose("a comfy sofa", quantity=2, variance="same", rng=np.random.default_rng(0))
    assert counting_encoder.seen.count("a comfy sofa") == 1


def test_unwritable_library_works_in_memory_with_a_note(library_factory, counting_encoder):
    library = library_factory([SOFA, BED])
    (library.root / ".cache").write_text("a file where the cache folder should be")
    retriever = AssetRetriever(library, encoder=counting_encoder)
    assert retriever.rank("a double bed")[0].asset_id == "bed_a"
    assert retriever.rank("a sofa")[0].asset_id == "sofa_a"
    notes = [n for n in retriever.notes if "kept in memory" in n]
    assert len(notes) == 1 and "cannot write the embedding cache" in notes[0]


def test_unreadable_cache_file_is_replaced(library_factory, counting_encoder):
    library = library_factory([SOFA, BED])
    path = cache_file(library.root, counting_encoder.name)
    path.parent.mkdir(parents=True)
    path.write_bytes(b"not an npz file")
    retriever = AssetRetriever(library, encoder=counting_encoder)
    assert retriever.rank("a sofa")[0].asset_id == "sofa_a"
    assert any("unreadable embedding cache" in n for n in retriever.notes)
    assert cached_keys(library, counting_encoder) == asset_keys(library, counting_encoder)


def test_embedding_cache_unit(tmp_path):
    calls: list[list[int]] = []

    def compute(indices: list[int]) -> np.ndarray:
        calls.append(indices)
        return np.array([[float(i), 1.0] for i in indices], dtype=np.float32)

    path = tmp_path / "c" / "m.npz"
    first = EmbeddingCache(path).fetch(["a", "b", "c"], compute)
    assert first.shape == (3, 2) and first.dtype == np.float32
    cache = EmbeddingCache(path)
    again = cache.fetch(["c", "a", "d"], lambda idx: compute(idx) + 10)
    assert calls[-1] == [2]  # only "d"
    np.testing.assert_array_equal(again[:2], first[[2, 0]])
    assert (cache.stats.hits, cache.stats.computed, cache.stats.written) == (2, 1, True)
    with np.load(path) as data:
        assert sorted(data["keys"].tolist()) == ["a", "c", "d"]  # "b" dropped
    memory = EmbeddingCache(None)
    assert memory.fetch(["x"], compute).shape == (1, 2) and not memory.stats.written
    with pytest.raises(ValueError, match="returned shape"):
        EmbeddingCache(None).fetch(["x", "y"], lambda idx: np.zeros((1, 2)))


def test_content_key_separates_parts():
    assert content_key("ab", "c") != content_key("a", "bc")
    assert content_key("m", b"\x00") == content_key("m", b"\x00")
    assert len(content_key("x")) == 64
