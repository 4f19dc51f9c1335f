"""The visual term V with a randomly initialised CLIP-like model.

No CLIP weights can be had offline, and open-clip-torch cannot be imported here (the only
torchvision wheel on PyPI for Linux is built against CUDA torch and fails to load beside the
CPU torch of this environment). So, when ``open_clip`` does not import, these tests build
:class:`TinyClip`, a small randomly initialised torch module with CLIP's interface
(``encode_image(images)``, ``encode_text(tokens)``, ``visual.image_size``) and a byte-level
tokenizer, and feed it through the same code: the open_clip adapter is exercised with a
stand-in ``open_clip`` module whose ``create_model(arch, pretrained=path)`` and
``get_tokenizer(arch)`` return them. When ``open_clip`` imports, the ranking test uses
``open_clip.create_model(arch, pretrained=None)`` instead.
"""

from __future__ import annotations

import sys
import types
from pathlib import Path

import numpy as np
import pytest
import torch
from PIL import Image

from holomj.errors import InputError
from holomj.retrieval.assets import AssetRetriever, retriever_for
from holomj.retrieval.cache import cache_file
from holomj.retrieval.scores import RetrievalWeights
from holomj.retrieval.visual import (
    CLIP_MEAN,
    CLIP_STD,
    VisualScorer,
    best_view_score,
    import_open_clip,
    load_rgb,
    model_image_size,
    open_clip_scorer,
    preprocess,
)
from tests.retrieval.conftest import AssetSpec

CONTEXT = 24


class TinyClip(torch.nn.Module):
    """A small randomly initialised CLIP-like model: conv image tower, bag-of-bytes text tower."""

    def __init__(self, dim: int = 32, image_size: int = 32, seed: int = 0) -> None:
        super().__init__()
        self.visual = torch.nn.Module()
        self.visual.image_size = image_size
        self.conv = torch.nn.Conv2d(3, 8, kernel_size=4, stride=4)
        self.image_proj = torch.nn.Linear(8 * (image_size // 4) ** 2, dim)
        self.embed = torch.nn.Embedding(257, dim)
        self.text_proj = torch.nn.Linear(dim, dim)
        generator = torch.Generator().manual_seed(seed)
        with torch.no_grad():
            for param in self.parameters():
                param.copy_(torch.randn(param.shape, generator=generator) * 0.3)
        self.image_calls = 0
        self.images_seen = 0

    def encode_image(self, images: torch.Tensor) -> torch.Tensor:
        self.image_calls += 1
        self.images_seen += images.shape[0]
        return self.image_proj(torch.relu(self.conv(images)).flatten(1))

    def encode_text(self, tokens: torch.Tensor) -> torch.Tensor:
        mask = (tokens > 0).float().unsqueeze(-1)
        pooled = (self.embed(tokens) * mask).sum(1) / mask.sum(1).clamp(min=1.0)
        return self.text_proj(pooled)


def tiny_tokenizer(texts: list[str]) -> torch.Tensor:
    """Bytes + 1, cut or zero-padded to CONTEXT."""
    rows = [[b + 1 for b in t.encode("utf-8")[:CONTEXT]] for t in texts]
    return torch.tensor([r + [0] * (CONTEXT - len(r)) for r in rows], dtype=torch.long)


def clip_model_and_tokenizer():
    """open_clip's randomly initialised ViT-B-32 when open_clip imports, else TinyClip."""
    try:
        import open_clip
    except Exception:
        return TinyClip(), tiny_tokenizer, "tiny-random-clip"
    torch.manual_seed(0)
    arch = "ViT-B-32"
    return open_clip.create_model(arch, pretrained=None), open_clip.get_tokenizer(arch), arch


def solid(path: Path, rgb: tuple[int, int, int], size: tuple[int, int] = (40, 30)) -> Path:
    Image.new("RGB", size, rgb).save(path)
    return path


def test_preprocess_resizes_crops_and_normalises(tmp_path):
    wide = Image.new("RGB", (400, 100), (0, 0, 255))
    wide.paste((255, 0, 0), (0, 0, 100, 100))  # the left quarter is red: cropped away
    out = preprocess(wide, 32)
    assert out.shape == (3, 32, 32) and out.dtype == np.float32
    blue = (np.array([0.0, 0.0, 1.0]) - CLIP_MEAN) / CLIP_STD
    np.testing.assert_allclose(out.reshape(3, -1).mean(axis=1), blue, atol=1e-4)
    clear = tmp_path / "clear.png"
    Image.new("RGBA", (20, 20), (10, 200, 10, 0)).save(clear)
    white = (np.ones(3) - CLIP_MEAN) / CLIP_STD
    np.testing.assert_allclose(
        preprocess(load_rgb(clear), 16).reshape(3, -1).mean(axis=1), white, atol=1e-4
    )
    bad = tmp_path / "bad.png"
    bad.write_text("not an image")
    with pytest.raises(InputError, match="cannot read image"):
        load_rgb(bad)


def test_scorer_shapes_batches_and_normalisation(tmp_path):
    model = TinyClip(dim=24, image_size=32)
    scorer = VisualScorer(model, tiny_tokenizer, name="tiny", image_size=32, batch_size=2)
    paths = [solid(tmp_path / f"{k}.png", (40 * k, 100, 200 - 30 * k)) for k in range(5)]
    images = scorer.encode_images(paths)
    assert images.shape == (5, 24) and images.dtype == np.float32
    np.testing.assert_allclose(np.linalg.norm(images, axis=1), 1.0, atol=1e-5)
    assert model.image_calls == 3  # batches of 2, 2, 1
    texts = scorer.encode_texts(["a red chair", "a blue sofa"])
    assert texts.shape == (2, 24)
    np.testing.assert_allclose(np.linalg.norm(texts, axis=1), 1.0, atol=1e-5)
    assert best_view_score(texts[0], images[:3]) == pytest.approx(
        float(np.max(images[:3] @ texts[0]))
    )


def test_visual_term_changes_the_ranking_and_is_cached(library_factory, encoder, tmp_path):
    model, tokenizer, name = clip_model_and_tokenizer()
    scorer = VisualScorer(model, tokenizer, name=name, image_size=model_image_size(model))
    colours = {"chair_a": (200, 30, 30), "chair_b": (30, 200, 30), "chair_c": (30, 30, 200)}
    thumbs = {
        i: (
            solid(tmp_path / f"{i}_0.png", rgb),
            solid(tmp_path / f"{i}_1.png", tuple((c + 128) // 2 for c in rgb)),
        )
        for i, rgb in colours.items()
    }
    query = "a red wooden chair"
    text_vec = scorer.encode_texts([query])[0]
    expected_v = {
        i: best_view_score(text_vec, scorer.encode_images(list(p))) for i, p in thumbs.items()
    }
    by_v = sorted(expected_v, key=expected_v.get)
    assert expected_v[by_v[-1]] - expected_v[by_v[0]] > 1e-4
    # The text favours the asset the model likes least.
    texts = {by_v[0]: query, by_v[1]: "a green office chair", by_v[2]: "a blue metal chair"}
    library = library_factory(
        [AssetSpec(i, "chair", texts[i], thumbnails=thumbs[i]) for i in sorted(colours)]
    )

    heavy_v = AssetRetriever(
        library, encoder=encoder, visual=scorer, weights=RetrievalWeights(1e4, 1.0, 0.0)
    )
    ranked = heavy_v.rank(query)
    assert ranked[0].asset_id == by_v[-1]
    assert [s.asset_id for s in ranked] == by_v[::-1]
    for s in ranked:
        assert s.visual == pytest.approx(expected_v[s.asset_id], abs=1e-5)
        assert s.score == pytest.approx(1e4 * s.visual + s.text, abs=1e-3)
    assert not any("CLIP weights" in n for n in heavy_v.notes)

    no_v = AssetRetriever(library, encoder=encoder, visual=scorer, weights=RetrievalWeights(0.0))
    ranked = no_v.rank(query)
    assert ranked[0].asset_id == by_v[0] and ranked[0].visual is None

    # Image embeddings are cached in the library, keyed by the thumbnails' bytes.
    path = cache_file(library.root, name)
    with np.load(path) as data:
        assert data["vectors"].shape[0] == 6
    if isinstance(model, TinyClip):
        seen = model.images_seen
        again = AssetRetriever(library, encoder=encoder, visual=scorer).rank(query)
        assert model.images_seen == seen  # nothing re-encoded
        assert again[0].asset_id == by_v[-1]
        solid(library.root / by_v[0] / "thumb_1.png", (255, 255, 0))  # one thumbnail changed
        AssetRetriever(library, encoder=encoder, visual=scorer).rank(query)
        assert model.images_seen == seen + 1


def test_assets_without_thumbnails_get_the_median(library_factory, encoder, tmp_path):
    scorer = VisualScorer(TinyClip(), tiny_tokenizer, name="tiny", image_size=32)
    red, blue, green = (
        solid(tmp_path / f"{c}.png", rgb)
        for c, rgb in [("r", (255, 0, 0)), ("b", (0, 0, 255)), ("g", (0, 255, 0))]
    )
    library = library_factory(
        [
            AssetSpec("vase_a", "vase", "a vase", placement=("object",), thumbnails=(red,)),
            AssetSpec("vase_b", "vase", "a vase", placement=("object",), thumbnails=(blue,)),
            AssetSpec("vase_c", "vase", "a vase", placement=("object",), thumbnails=(green,)),
            AssetSpec("vase_d", "vase", "a vase", placement=("object",)),
        ]
    )
    retriever = AssetRetriever(library, encoder=encoder, visual=scorer)
    ranked = {s.asset_id: s for s in retriever.rank("a vase", placement="object")}
    assert ranked["vase_d"].visual is None
    median = float(np.median([ranked[i].visual for i in ("vase_a", "vase_b", "vase_c")]))
    assert ranked["vase_d"].score == pytest.approx(100 * median + ranked["vase_d"].text, abs=1e-4)
    assert any("median visual score" in n for n in retriever.notes)
    bare = library_factory([AssetSpec("vase_d", "vase", "a vase", placement=("object",))])
    retriever = AssetRetriever(bare, encoder=encoder, visual=scorer)
    assert retriever.rank("a vase", placement="object")[0].visual is None
    assert any("no candidate asset has thumbnails" in n for n in retriever.notes)


@pytest.fixture
def fake_open_clip(monkeypatch):
    """A stand-in ``open_clip`` module (only when the real one cannot be imported)."""
    try:
        import open_clip  # noqa: F401
    except Exception:
        pass
    else:
        pytest.skip("open_clip is importable here: the stand-in is not needed")
    calls: list[tuple[str, str | None]] = []
    module = types.ModuleType("open_clip")

    def create_model(arch: str, pretrained: str | None = None) -> TinyClip:
        calls.append((arch, pretrained))
        model = TinyClip(image_size=48)
        if pretrained is not None:
            model.load_state_dict(torch.load(pretrained, weights_only=True), strict=False)
        return model

    module.create_model = create_model
    module.get_tokenizer = lambda arch: tiny_tokenizer
    monkeypatch.setitem(sys.modules, "open_clip", module)
    return calls


def test_open_clip_adapter_loads_local_weights(fake_open_clip, tmp_path, monkeypatch):
    weights = tmp_path / "tiny.pt"
    torch.save(TinyClip(image_size=48, seed=3).state_dict(), weights)
    scorer = open_clip_scorer(weights, "TinyArch")
    assert fake_open_clip == [("TinyArch", str(weights))]
    assert scorer.image_size == 48 and scorer.name.startswith("clip-TinyArch-")
    reference = TinyClip(image_size=48, seed=3)
    tokens = tiny_tokenizer(["a 3D model of a lamp"])
    with torch.no_grad():
        expected = reference.encode_text(tokens)[0].numpy()
    np.testing.assert_allclose(
        scorer.encode_texts(["a lamp"])[0], expected / np.linalg.norm(expected), atol=1e-5
    )
    monkeypatch.setenv("HOLOMJ_CLIP_WEIGHTS", str(weights))
    monkeypatch.setenv("HOLOMJ_CLIP_MODEL", "EnvArch")
    from holomj.library import AssetLibrary

    retriever = retriever_for(AssetLibrary.open(_empty_library(tmp_path)), encoder=object())
    assert retriever.notes == [] and fake_open_clip[-1] == ("EnvArch", str(weights))


def _empty_library(tmp_path: Path) -> Path:
    root = tmp_path / "lib"
    root.mkdir()
    (root / "library.json").write_text('{"schema_version": "1.0", "name": "e", "assets": {}}')
    return root


def test_missing_open_clip_names_the_extra(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "open_clip", None)  # import open_clip -> ImportError
    with pytest.raises(InputError, match=r"holomj\[clip\]"):
        import_open_clip()
    weights = tmp_path / "w.pt"
    weights.write_bytes(b"0")
    with pytest.raises(InputError, match=r"holomj\[clip\]"):
        open_clip_scorer(weights)
    with pytest.raises(InputError, match="CLIP weights file not found"):
        open_clip_scorer(tmp_path / "absent.pt")
