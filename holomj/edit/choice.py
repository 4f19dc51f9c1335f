"""The asset an ``add`` or ``replace`` gets: retrieval for the described object, its size
checked, and the pick's record for the edit report."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from holomj.edit.describe import Described
from holomj.edit.state import (
    EditContext,
    Refused,
    check_size,
)
from holomj.errors import HolomjError
from holomj.spec.assets import AssetMeta


def retrieve(
    ctx: EditContext,
    asked: Described,
    *,
    attributes: Sequence[str],
    category: str | None,
    size: tuple[float, float, float] | None,
    placement: str,
    key: tuple[object, ...],
) -> tuple[str, dict[str, Any]]:
    """One asset for the described object: its id and the pick's record."""
    text = " ".join([asked.description, *attributes])
    try:
        pick = ctx.retriever.choose(
            text,
            quantity=1,
            variance="same",
            rng=ctx.rng(*key),
            size=size,
            placement=placement,
            category=category,
        )[0]
    except HolomjError as err:
        raise Refused(f"no asset for {asked.description!r}: {err.one_line()}") from None
    record: dict[str, Any] = {"asset": pick.asset_id, "query": text}
    for name in ("category", "score", "how", "proxy", "attributes_asked", "attributes_honoured"):
        value = getattr(pick, name, None)
        if value is not None:
            record[name] = round(value, 4) if isinstance(value, float) else value
    return pick.asset_id, record


def choose_asset(
    ctx: EditContext,
    asked: Described,
    *,
    attributes: Sequence[str],
    category: str | None,
    size: tuple[float, float, float] | None,
    placement: str,
    key: tuple[object, ...],
) -> tuple[str, AssetMeta, dict[str, Any]]:
    """:func:`retrieve`, with the chosen asset's metadata, its size checked (an absurd size is
    refused)."""
    asset_id, pick = retrieve(
        ctx, asked, attributes=attributes, category=category, size=size,
        placement=placement, key=key,
    )  # fmt: skip
    meta = ctx.library.get(asset_id).meta
    check_size(meta.size, f"asset {asset_id}")
    return asset_id, meta, pick
