"""The plain-PyTorch MiniLM encoder: sentence-transformers' vectors, without its import."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from holomj.retrieval.minilm import MiniLMEncoder, supports
from holomj.retrieval.text import (
    DEFAULT_MODEL_NAME,
    TEXT_BACKEND_ENV,
    TEXT_MODEL_ENV,
    default_model_path,
    text_encoder,
)

LONG = " ".join(
    f"the {adjective} table number {k} stands next to a lamp, a rug and two chairs;"
    for k, adjective in enumerate(["oak", "pine", "glass", "steel", "marble"] * 12)
)

TEXTS = [
    "",
    " ",
    "chair",
    "Chair",
    "CHAIR",
    "a",
    "sofa",
    "lamp",
    "bed",
    "tv",
    "a wooden dining chair with four legs",
    "A modern L-shaped sectional sofa in grey fabric.",
    "bedroom",
    "living room",
    "kitchen with an island and bar stools",
    "oak",
    "brushed steel",
    "white marble with grey veins",
    "Café crème — naïve résumé, piñata, Über, façade",
    "Ångström ÉCOLE Zoë Øresund",
    "!!!",
    "???...,,,;;;",
    "(a) [b] {c} <d> 'e' \"f\"",
    "price: $1,299.99 (-20%) #deal @store & more",
    "email: someone@example.com, url: https://example.com/a?b=c",
    "snake_case and kebab-case and camelCase words",
    "3 chairs, 2 tables and 1 lamp",
    "123456789 0.5 1e-3 42",
    "line one\nline two\tand a tab",
    "   leading and trailing spaces   ",
    "日本語のテキスト",
    "中文的椅子和桌子",
    "Привет, мир",
    "مرحبا بالعالم",
    "emoji 🪑 chair 🛋️ sofa",
    "a " * 300,
    "word " * 255,
    "word " * 254,
    "supercalifragilisticexpialidocious antidisestablishmentarianism",
    LONG,
    LONG.upper(),
    "x" * 1000,
    "a tall narrow bookshelf filled with books, plants and small decorative objects",
    "a round coffee table",
    "a rectangular coffee table",
    "bathroom sink with a mirror above it",
    "office desk, ergonomic chair, monitor, keyboard",
    "outdoor patio with a grill",
    "the quick brown fox jumps over the lazy dog",
    "Scene: a cozy reading nook by the window.",
    "zzzz qqqq xxxx",
]


@pytest.fixture(scope="module")
def model_path() -> Path:
    return default_model_path()


@pytest.fixture(scope="module")
def minilm(model_path: Path) -> MiniLMEncoder:
    return MiniLMEncoder(model_path)


@pytest.fixture(scope="module")
def vectors(minilm: MiniLMEncoder) -> np.ndarray:
    return minilm.encode(TEXTS)


def test_packaged_model_is_supported(model_path: Path) -> None:
    assert supports(model_path)


def test_default_encoder_is_minilm_with_the_same_name(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(TEXT_MODEL_ENV, raising=False)
    monkeypatch.delenv(TEXT_BACKEND_ENV, raising=False)
    encoder = text_encoder()
    assert isinstance(encoder, MiniLMEncoder)
    assert encoder.name == DEFAULT_MODEL_NAME
    assert encoder.dim == 384


def test_shapes_norms_and_order(minilm: MiniLMEncoder, vectors: np.ndarray) -> None:
    assert minilm.encode([]).shape == (0, 384)
    assert vectors.shape == (len(TEXTS), 384)
    assert vectors.dtype == np.float32
    np.testing.assert_allclose(np.linalg.norm(vectors, axis=1), 1.0, atol=1e-5)
    # Each text alone gives the vector it got in the (length-sorted, padded) batch.
    for k in (0, 2, 18, 39):
        np.testing.assert_allclose(minilm.encode([TEXTS[k]])[0], vectors[k], atol=1e-5)
    assert float(vectors[TEXTS.index("chair")] @ vectors[TEXTS.index("sofa")]) > float(
        vectors[TEXTS.index("chair")] @ vectors[TEXTS.index("zzzz qqqq xxxx")]
    )


def test_small_batches_give_the_same_vectors(model_path: Path, vectors: np.ndarray) -> None:
    small = MiniLMEncoder(model_path, batch_size=3)
    picked = [k for k, text in enumerate(TEXTS) if len(text) < 80] + [TEXTS.index(LONG)]
    np.testing.assert_allclose(small.encode([TEXTS[k] for k in picked]), vectors[picked], atol=1e-5)


def test_unsupported_folders(tmp_path: Path, model_path: Path) -> None:
    assert not supports(tmp_path / "missing")
    assert not supports(tmp_path)
    modules = json.loads((model_path / "modules.json").read_text())
    (tmp_path / "modules.json").write_text(json.dumps(modules[:1]))
    assert not supports(tmp_path)


@pytest.mark.slow
def test_matches_sentence_transformers(model_path: Path, vectors: np.ndarray) -> None:
    pytest.importorskip("sentence_transformers")
    from holomj.retrieval.text import SentenceTransformerEncoder

    reference = SentenceTransformerEncoder(model_path).encode(TEXTS)
    ours = vectors
    cosines = np.sum(ours * reference, axis=1) / (
        np.linalg.norm(ours, axis=1) * np.linalg.norm(reference, axis=1)
    )
    assert cosines.min() > 0.99999, TEXTS[int(cosines.argmin())]
    assert np.abs(ours - reference).max() < 1e-4


def test_encoding_does_not_import_sentence_transformers() -> None:
    code = (
        "import sys\n"
        "from holomj.retrieval.text import text_encoder\n"
        "vectors = text_encoder().encode(['a wooden chair', 'a lamp'])\n"
        "assert vectors.shape == (2, 384), vectors.shape\n"
        "heavy = sorted(m for m in sys.modules\n"
        "               if m.split('.')[0] in ('sentence_transformers', 'transformers'))\n"
        "print(heavy)\n"
    )
    env = {k: v for k, v in os.environ.items() if k not in (TEXT_MODEL_ENV, TEXT_BACKEND_ENV)}
    done = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
        env=env,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]", done.stdout
