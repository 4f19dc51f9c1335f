"""The asset an added, replaced or light-fixture object gets: retrieval for the described object,
its size checked, and the pick's record for the edit report."""

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


def choose_asset(
    ctx: EditContext,
    asked: Described,
    *,
    attributes: Sequence[str],
    category: str | None,
    size: tuple[float, float, float] | None,
    placement: str,
    key: tuple[object, ...],
    refuse_absurd: bool = True,
) -> tuple[str, AssetMeta, dict[str, Any]]:
    """One asset for the described object: its id, its metadata and the pick's record; with
    ``refuse_absurd``, an asset of an absurd size is refused."""
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
    meta = ctx.library.get(pick.asset_id).meta
    if refuse_absurd:
        check_size(meta.size, f"asset {pick.asset_id}")
    return pick.asset_id, meta, record
