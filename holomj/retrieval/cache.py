"""A content-addressed embedding cache: one ``.npz`` file per model in the library folder.

Vectors are keyed by a hash of exactly what was embedded (the text, or the bytes of a
thumbnail) together with the model's name, so a changed description or image gets a new key and
is re-embedded, and a removed asset's vector is dropped the next time the file is written. The
file lives at ``LIB/.cache/retrieval/<model name>.npz`` and is written atomically (a temporary
file beside it, then a rename). A library that cannot be written still works: the vectors are
kept in memory and a note says so.
"""

from __future__ import annotations

import hashlib
import io
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from holomj.atomic import write_file

CACHE_SUBDIR = Path(".cache") / "retrieval"


def content_key(*parts: str | bytes) -> str:
    """A SHA-256 hex digest of ``parts`` (length-prefixed, so ``("ab", "c") != ("a", "bc")``)."""
    digest = hashlib.sha256()
    for part in parts:
        data = part.encode("utf-8") if isinstance(part, str) else part
        digest.update(len(data).to_bytes(8, "little"))
        digest.update(data)
    return digest.hexdigest()


def cache_file(library_root: Path, model_name: str) -> Path:
    """Where the embeddings of ``model_name`` for the library at ``library_root`` are kept."""
    safe = re.sub(r"[^A-Za-z0-9._-]+", "_", model_name).strip("._") or "model"
    return Path(library_root) / CACHE_SUBDIR / f"{safe}.npz"


@dataclass
class CacheStats:
    """What the last :meth:`EmbeddingCache.fetch` did."""

    hits: int = 0
    computed: int = 0
    written: bool = False


class EmbeddingCache:
    """Vectors keyed by content hash, persisted in one ``.npz`` file (or memory only).

    ``path`` None keeps everything in memory. Problems with the file never fail a lookup: an
    unreadable file is ignored (and replaced), an unwritable folder leaves the vectors in
    memory; both add a line to :attr:`notes`.
    """

    def __init__(self, path: Path | None) -> None:
        self.path = Path(path) if path is not None else None
        self.notes: list[str] = []
        self.stats = CacheStats()
        self._vectors: dict[str, np.ndarray] | None = None
        self._on_disk: frozenset[str] = frozenset()
        self._unwritable = False

    def fetch(self, keys: Sequence[str], compute: Callable[[list[int]], np.ndarray]) -> np.ndarray:
        """The vectors of ``keys`` as a (len(keys), dim) float32 array.

        Missing ones are computed with ``compute(indices)``, which returns one row per index
        (in order). When the set of keys differs from the file's, the file is rewritten with
        exactly ``keys``: entries of removed or changed inputs are dropped.
        """
        stored = self._load()
        missing = [i for i, key in enumerate(keys) if key not in stored]
        fresh = self._compute(compute, missing)
        if fresh is not None and stored:
            any_old = next(iter(stored.values()))
            if any_old.shape != fresh.shape[1:]:  # same name, another model: start over
                stored.clear()
                missing = list(range(len(keys)))
                fresh = self._compute(compute, missing)
        if fresh is not None:
            for row, index in enumerate(missing):
                stored[keys[index]] = fresh[row]
        self.stats = CacheStats(hits=len(keys) - len(missing), computed=len(missing))
        if not keys:
            return np.zeros((0, 0), dtype=np.float32)
        out = np.stack([stored[key] for key in keys]).astype(np.float32, copy=False)
        wanted = frozenset(keys)
        if wanted != self._on_disk and not self._unwritable:
            for key in set(stored) - wanted:
                del stored[key]
            self.stats.written = self._save(stored)
        return out

    def _compute(
        self, compute: Callable[[list[int]], np.ndarray], indices: list[int]
    ) -> np.ndarray | None:
        if not indices:
            return None
        rows = np.asarray(compute(indices), dtype=np.float32)
        if rows.ndim != 2 or rows.shape[0] != len(indices):
            raise ValueError(f"embedding function returned shape {rows.shape} for {len(indices)}")
        return rows

    def _load(self) -> dict[str, np.ndarray]:
        if self._vectors is not None:
            return self._vectors
        self._vectors = {}
        if self.path is None or not self.path.is_file():
            return self._vectors
        try:
            with np.load(self.path, allow_pickle=False) as data:
                keys = [str(k) for k in data["keys"]]
                vectors = np.asarray(data["vectors"], dtype=np.float32)
            if vectors.ndim != 2 or vectors.shape[0] != len(keys):
                raise ValueError(f"vectors of shape {vectors.shape} for {len(keys)} keys")
        except (OSError, KeyError, ValueError, EOFError) as err:
            self.notes.append(f"ignored an unreadable embedding cache {self.path} ({err})")
            return self._vectors
        self._vectors = dict(zip(keys, vectors))
        self._on_disk = frozenset(keys)
        return self._vectors

    def _save(self, vectors: dict[str, np.ndarray]) -> bool:
        if self.path is None:
            return False
        keys = sorted(vectors)
        dim = next(iter(vectors.values())).shape[0] if vectors else 0
        matrix = np.stack([vectors[k] for k in keys]) if keys else np.zeros((0, dim), np.float32)
        buffer = io.BytesIO()
        np.savez(buffer, keys=np.array(keys, dtype="<U64"), vectors=matrix)
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            write_file(self.path, buffer.getvalue())
        except OSError as err:
            self.notes.append(
                f"cannot write the embedding cache {self.path} "
                f"({err.strerror or err}): embeddings are kept in memory only"
            )
            self._unwritable = True
            return False
        self._on_disk = frozenset(keys)
        return True
