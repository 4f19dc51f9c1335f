"""Fixtures of the retrieval tests: one text encoder per session, small hand-made libraries."""

from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from holomj.library import AssetLibrary
from holomj.retrieval.text import TextEncoder

UNIT_BOX_OBJ = """v -0.5 -0.5 0
v 0.5 -0.5 0
v 0.5 0.5 0
v -0.5 0.5 0
v -0.5 -0.5 1
v 0.5 -0.5 1
v 0.5 0.5 1
v -0.5 0.5 1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 4 1 5
f 4 5 8
"""


@pytest.fixture(scope="session")
def encoder() -> TextEncoder:
    """The shipped all-MiniLM-L6-v2 encoder, loaded once (about 10 s)."""
    from holomj.retrieval.text import text_encoder

    return text_encoder()


class CountingEncoder:
    """Wraps an encoder and records every text it embeds."""

    def __init__(self, inner: TextEncoder) -> None:
        self.inner = inner
        self.name = inner.name
        self.dim = inner.dim
        self.seen: list[str] = []

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        self.seen.extend(texts)
        return self.inner.encode(texts)


@pytest.fixture
def counting_encoder(encoder: TextEncoder) -> CountingEncoder:
    """A fresh :class:`CountingEncoder` around the session encoder."""
    return CountingEncoder(encoder)


@dataclass(frozen=True)
class AssetSpec:
    """What a hand-made test asset needs: id, category, description, size, placement."""

    id: str
    category: str
    description: str = ""
    size: tuple[float, float, float] = (0.5, 0.5, 0.5)
    placement: tuple[str, ...] = ("floor",)
    thumbnails: tuple[Path, ...] = ()


def write_library(root: Path, assets: Sequence[AssetSpec], name: str = "test") -> AssetLibrary:
    """(Re)write a library at ``root`` holding exactly ``assets`` (a box mesh each); open it.

    Thumbnail files are copied into each asset's folder. Existing asset folders and the
    library's ``.cache`` are kept, so a rewrite looks like assets added, changed or removed.
    """
    root.mkdir(parents=True, exist_ok=True)
    index = {}
    for spec in assets:
        folder = root / spec.id
        folder.mkdir(exist_ok=True)
        (folder / "box.obj").write_text(UNIT_BOX_OBJ)
        thumbs = []
        for k, source in enumerate(spec.thumbnails):
            rel = f"thumb_{k}.png"
            (folder / rel).write_bytes(Path(source).read_bytes())
            thumbs.append(rel)
        sx, sy, sz = spec.size
        meta = {
            "id": spec.id,
            "category": spec.category,
            "description": spec.description,
            "size": list(spec.size),
            "placement": list(spec.placement),
            "visual": [{"mesh": "box.obj"}],
            "collision": [
                {"kind": "box", "size": [sx / 2, sy / 2, sz / 2], "volume_m3": sx * sy * sz}
            ],
            "thumbnails": thumbs,
        }
        (folder / "asset.json").write_text(json.dumps(meta))
        index[spec.id] = spec.id
    (root / "library.json").write_text(
        json.dumps({"schema_version": "1.0", "name": name, "assets": index})
    )
    return AssetLibrary.open(root)


@pytest.fixture
def library_factory(tmp_path: Path) -> Callable[..., AssetLibrary]:
    """``make(assets, name=...)``: a library in this test's temp folder (the same each call)."""

    def make(assets: Sequence[AssetSpec], name: str = "test") -> AssetLibrary:
        return write_library(tmp_path / "library", assets, name)

    return make
