"""Choosing library assets for plan objects: one per instance, among the best ranked
(:mod:`holomj.retrieval.ranking`, Holodeck's score M = α·V + β·T − γ·S).

**Assets on demand** (with a ``synthesiser``, :class:`holomj.jobs.synthesis.LibrarySynthesiser`,
as ``generate`` passes one): :meth:`AssetRetriever.choose` reads the attributes the description
asks (colour, material, shape, style, and the colour or material of parts: ``"brass handles"``
reads ``{"handles.material": "brass"}``) and

- when the category (or an alias) has library assets, chooses among those whose attributes
  (recorded, else read from their description) match the colour, material, shape and part
  attributes asked ("library match"); when none does, it synthesises one of that category with
  them (each pick says per part how it was honoured, or why not: ``attributes_how``)
  ("synthesised"), or, without a generator for the category, takes the best asset and says the
  attributes were not honoured ("library");
- when the category has no library asset, it synthesises one if a generator exists, else takes
  another category only when the two category names are nearly synonyms, text cosine at least
  :data:`SIMILARITY_FLOOR` ("similar category"), and otherwise builds a proxy ("proxy"): another
  category is never passed off as the asked one.

Assets made on demand are never ranked (their ids are recomputed from the request), so a run's
choices do not depend on what earlier runs synthesised. Without a synthesiser, ``choose`` ranks
as before (every asset scored when the category is unknown, with a note).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
from typing_extensions import Unpack

from holomj.errors import InputError
from holomj.library.store import AssetLibrary
from holomj.retrieval.ranking import AssetRanker, RankerOptions
from holomj.retrieval.scores import (
    DEFAULT_WEIGHTS,
    RetrievalWeights,
    ScoredAsset,
    check_placement,
    check_size,
    size_discrepancy,
)
from holomj.retrieval.text import TextEncoder
from holomj.retrieval.visual import visual_scorer_from_env
from holomj.spec.categories import asset_axes, normalise_category

SIMILARITY_FLOOR = 0.8
"""Least text cosine between two category names for one to stand in for the other (with the
default MiniLM encoder, couch/sofa and bookcase/bookshelf pass; treadmill/desk, 0.2-0.4, and
kettlebell/pot do not). Listed stand-ins (``category_facts.json``) always pass."""
SYNTH_STYLES = 4
"""Style seeds an asset made on demand is drawn from (the run's generator picks one)."""
VARIED_POOL = 3
"""``varied``: instances draw from the best asset and up to this many more of its category."""


class AssetRetriever(AssetRanker):
    """Chooses a library's assets for plan objects (an
    :class:`~holomj.retrieval.chooser.AssetChooser`), making them on demand with a
    ``synthesiser`` (see the module docstring)."""

    def __init__(
        self, library: AssetLibrary, *, synthesiser: Any = None, **options: Unpack[RankerOptions]
    ) -> None:
        super().__init__(library, **options)
        self.synthesiser = synthesiser
        self._recorded: dict[int, dict[str, str]] = {}

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
    ) -> list[ScoredAsset]:
        """One asset per instance: all the best one (``same``) or different ones (``varied``).

        ``varied`` keeps the best asset and draws the others without replacement from the
        next ``max(quantity - 1, VARIED_POOL)`` candidates of the best one's category; when
        fewer exist, assets repeat. The instance order is shuffled with ``rng``.
        """
        if quantity < 1:
            raise InputError(f"quantity must be at least 1, got {quantity}", where=description)
        if variance not in ("same", "varied"):
            raise InputError(
                f"unknown variance {variance!r}", where=description, fix="use same or varied"
            )
        if self.synthesiser is not None:
            return self._choose_on_demand(
                description, quantity, variance, rng, size, placement, category
            )
        rows = self._candidates(description, placement, category)
        return self._pick(description, size, rows, quantity, variance, rng)

    def _pick(
        self,
        description: str,
        size: tuple[float, float, float] | None,
        rows: np.ndarray,
        quantity: int,
        variance: str,
        rng: np.random.Generator,
    ) -> list[ScoredAsset]:
        """``quantity`` picks among ``rows``, as :meth:`choose` describes."""
        best = self._top(description, size, rows, 1)[0]
        if variance == "same" or quantity == 1:
            return [best] * quantity
        same_kind = self.index.of_category_name(rows, best.category)
        pool = self._top(description, size, same_kind, 1 + max(quantity - 1, VARIED_POOL))
        extra = min(quantity - 1, len(pool) - 1)
        picks = [best]
        if extra > 0:
            drawn = rng.choice(np.arange(1, len(pool)), size=extra, replace=False)
            picks += [pool[int(k)] for k in drawn]
        chosen = [picks[k % len(picks)] for k in range(quantity)]
        order = rng.permutation(quantity)
        return [chosen[int(k)] for k in order]

    def _choose_on_demand(
        self,
        description: str,
        quantity: int,
        variance: str,
        rng: np.random.Generator,
        size: tuple[float, float, float] | None,
        placement: str,
        category: str | None,
    ) -> list[ScoredAsset]:
        syn = self.synthesiser
        asked = syn.parse(description, category)
        hard = {k: v for k, v in asked.items() if k != "style"}
        rows = self._own_candidates(description, placement, category)
        if category is None and rows.size:
            category = self._top(description, size, rows, 1)[0].category
            rows = self.index.of_category_name(rows, category)
        if rows.size:
            if not hard:
                picks = self._pick(description, size, rows, quantity, variance, rng)
                return [self._labelled(p, "library", asked) for p in picks]
            matching = np.array(
                [r for r in rows if _matches(self._recorded_of(int(r)), hard)], dtype=np.int64
            )
            if matching.size:
                picks = self._pick(description, size, matching, quantity, variance, rng)
                return [self._labelled(p, "library match", asked) for p in picks]
            best = self._top(description, size, rows, 1)[0]
            generator = syn.generator_for(category) or syn.generator_for(best.category)
            if generator is None:
                self._note(
                    f"no {best.category} asset is {_words(hard)} and no generator makes "
                    f"one: {description!r} gets the best {best.category} as it is"
                )
                picks = self._pick(description, size, rows, quantity, variance, rng)
                return [self._labelled(p, "library", asked) for p in picks]
            return [self._synthesised(description, generator, size, asked, rng)] * quantity
        generator = syn.generator_for(category)
        if generator is not None:
            return [self._synthesised(description, generator, size, asked, rng)] * quantity
        similar = self._similar_category(category, placement)
        if similar is not None:
            self._note(
                f"no {placement} asset of category {category!r} in library "
                f"{self.library.name!r}: its near synonym {similar!r} stands in for "
                f"{description!r}"
            )
            pool = self.index.of_categories(self._placed(placement), {normalise_category(similar)})
            picks = self._pick(description, size, pool, quantity, variance, rng)
            return [self._labelled(p, "similar category", asked) for p in picks]
        return [self._proxy(description, category, size, placement, asked)] * quantity

    def _recorded_of(self, row: int) -> dict[str, str]:
        """The attributes an asset records (or its description says), read once."""
        if row not in self._recorded:
            self._recorded[row] = self.synthesiser.recorded(self._assets[row])
        return self._recorded[row]

    def _placed(self, placement: str) -> np.ndarray:
        """Mask of the library's own assets (none made on demand) allowing ``placement``."""
        return self.index.placed(placement, own_only=True)

    def _own_candidates(self, description: str, placement: str, category: str | None) -> np.ndarray:
        """Rows of the library's own assets (none made on demand) of ``category`` or its
        aliases."""
        check_placement(placement, description)
        placed = self._placed(placement)
        if category is None:
            return np.flatnonzero(placed)
        return self._of_category(placed, category)

    def _labelled(self, pick: ScoredAsset, how: str, asked: dict[str, str]) -> ScoredAsset:
        honoured: dict[str, str] = {}
        if asked and how == "library match":
            recorded = self._recorded_of(self._index_of[pick.asset_id])
            honoured = {k: v for k, v in asked.items() if recorded.get(k) == v}
        parts = {k.partition(".")[0] for k in asked if "." in k}
        parts_how = {
            role: (
                "recorded by the library asset"
                if any(k.startswith(f"{role}.") for k in honoured)
                else f"not honoured: the {how} asset does not record it"
            )
            for role in sorted(parts)
        }
        return replace(
            pick,
            how=how,
            attributes_asked=asked,
            attributes_honoured=honoured,
            attributes_how=parts_how or None,
        )

    def _synthesised(
        self,
        description: str,
        category: str,
        size: tuple[float, float, float] | None,
        asked: dict[str, str],
        rng: np.random.Generator,
    ) -> ScoredAsset:
        target = None if size is None else asset_axes(check_size(size, description))
        seed = int(rng.integers(SYNTH_STYLES))
        made = self.synthesiser.synthesise(category, target, seed, asked)
        for note in made.notes:
            self._note(f"{description!r}: {made.asset_id}: {note}")
        return self._scored_new(description, size, made, "synthesised", asked)

    def _proxy(
        self,
        description: str,
        category: str | None,
        size: tuple[float, float, float] | None,
        placement: str,
        asked: dict[str, str],
    ) -> ScoredAsset:
        label = category or description
        target = asset_axes(check_size(size, description)) if size is not None else None
        if target is None:
            target = _DEFAULT_PROXY_SIZE.get(placement, (0.5, 0.5, 0.5))
        made = self.synthesiser.proxy(label, target, placement, asked)
        self._note(
            f"no {placement} asset or generator of category {label!r}: {description!r} is a "
            f"proxy ({made.family}, {made.asset_id})"
        )
        for note in made.notes:
            self._note(f"{description!r}: {made.asset_id}: {note}")
        return self._scored_new(description, size, made, "proxy", asked)

    def _scored_new(
        self,
        description: str,
        size: tuple[float, float, float] | None,
        made: Any,
        how: str,
        asked: dict[str, str],
    ) -> ScoredAsset:
        asset = self.library.get(made.asset_id)
        text = float((self.vectors.text_of(asset) * self.vectors.text_query(description)).sum())
        sizes = 0.0
        if size is not None:
            sizes = size_discrepancy(check_size(size, description), asset.meta.size)
        w = self.weights
        return ScoredAsset(
            asset_id=made.asset_id,
            category=made.category,
            score=float((w.text + w.visual) * text - w.size * sizes),
            visual=None,
            text=text,
            size=float(sizes),
            how=how,
            attributes_asked=asked,
            attributes_honoured=dict(made.attributes_honoured),
            attributes_how=dict(getattr(made, "parts_how", {}) or {}) or None,
            proxy=how == "proxy",
        )

    def _similar_category(self, category: str | None, placement: str) -> str | None:
        """The library category whose name is closest to ``category`` in text, when its cosine
        is at least :data:`SIMILARITY_FLOOR`; else None."""
        if category is None:
            return None
        names = sorted(set(self.index.categories[self._placed(placement)].tolist()))
        if not names:
            return None
        wanted = self.vectors.category_vector(category)
        best, best_name = -1.0, None
        for name in names:
            value = float((self.vectors.category_vector(name) * wanted).sum())
            if value > best:
                best, best_name = value, name
        return best_name if best >= SIMILARITY_FLOOR else None


_DEFAULT_PROXY_SIZE = {
    "floor": (0.6, 0.6, 0.8),
    "wall": (0.04, 0.8, 0.6),
    "ceiling": (0.5, 0.5, 0.4),
    "object": (0.15, 0.15, 0.15),
}


def _matches(recorded: dict[str, str], hard: dict[str, str]) -> bool:
    return all(recorded.get(k) == v for k, v in hard.items())


def _words(attributes: dict[str, str]) -> str:
    return " ".join(attributes.values())


def retriever_for(
    library: AssetLibrary,
    *,
    clip_weights: Path | None = None,
    clip_model: str | None = None,
    encoder: TextEncoder | None = None,
    weights: RetrievalWeights = DEFAULT_WEIGHTS,
    synthesiser: Any = None,
) -> AssetRetriever:
    """A retriever for ``library`` with the visual term when CLIP weights are configured.

    ``clip_weights`` (else ``$HOLOMJ_CLIP_WEIGHTS``) is a local open_clip checkpoint of the
    architecture ``clip_model`` (else ``$HOLOMJ_CLIP_MODEL``, default ViT-B-32). With a
    ``synthesiser`` the retriever makes assets on demand (see the module docstring).
    """
    visual = visual_scorer_from_env(clip_weights, clip_model)
    return AssetRetriever(
        library, encoder=encoder, visual=visual, weights=weights, synthesiser=synthesiser
    )
