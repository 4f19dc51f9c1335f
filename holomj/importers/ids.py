"""Turning foreign ids (``"living room"``, ``"sofa-0 (living room)"``) into holomj identifiers.

holomj ids match ``^[A-Za-z0-9_][A-Za-z0-9_.:|+\\-]*$`` (at most 128 characters). The mapping is
deterministic: whitespace runs become ``_``, other characters outside the allowed set are
dropped, and a clash with an id already handed out gets a ``_2``, ``_3``... suffix.
"""

from __future__ import annotations

import re

_ALLOWED = re.compile(r"[^A-Za-z0-9_.:|+\-]")
_LEADING = re.compile(r"^[^A-Za-z0-9_]+")
_MAX_LEN = 120


def sanitise(raw: str, fallback: str = "id") -> str:
    """A valid holomj identifier made from ``raw`` (``fallback`` if nothing is left)."""
    text = re.sub(r"\s+", "_", raw.strip())
    text = _ALLOWED.sub("", text)
    text = _LEADING.sub("", text)
    text = text[:_MAX_LEN]
    return text or fallback


class IdMap:
    """Hands out unique sanitised ids for one namespace, remembering raw -> new."""

    def __init__(self, fallback: str) -> None:
        self.fallback = fallback
        self._used: set[str] = set()
        self._by_raw: dict[str, str] = {}

    def new(self, raw: str | None) -> str:
        """A fresh unique id for ``raw`` (remembered for :meth:`lookup`, first one wins)."""
        base = sanitise(raw, self.fallback) if raw else self.fallback
        candidate = base
        counter = 2
        while candidate in self._used:
            suffix = f"_{counter}"
            candidate = base[: _MAX_LEN - len(suffix)] + suffix
            counter += 1
        self._used.add(candidate)
        if raw is not None and raw not in self._by_raw:
            self._by_raw[raw] = candidate
        return candidate

    def lookup(self, raw: str) -> str | None:
        """The id given to ``raw`` earlier, if any."""
        return self._by_raw.get(raw)
