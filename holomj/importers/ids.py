"""Foreign ids (``"living room"``, ``"sofa-0 (living room)"``) as holomj identifiers.

holomj ids match ``^[A-Za-z0-9_][A-Za-z0-9_.:|+\\-]*$`` (at most 128 characters). The mapping is
deterministic: whitespace runs become ``_``, other characters outside the allowed set are
dropped.

Two entries of one input that give the *same* id are a mistake in the input (two co-located
copies of a chair, say): :func:`check_unique_ids` rejects them before anything is imported,
naming both places. Ids that only clash once sanitised (``"a b"`` and ``"a_b"``), or that clash
with an id the importer made up for an entry without one, are not the user's duplicates: the
later one gets a ``_2``, ``_3``... suffix and, for an id the input gave, :class:`IdMap` records a
warning for ``import_report.json``.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from typing import Any

from holomj.errors import SpecError

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


def listed_ids(value: Any, path: str, children: str | None = None) -> Iterator[tuple[str, str]]:
    """``(id, JSON path of the id)`` for every entry of the list ``value`` found at ``path``.

    Entries are visited in document order; with ``children`` each entry's nested list of that
    name is visited right after the entry (``objects[2]``, ``objects[2].children[0]``,
    ``objects[3]``...), however deep. Anything not shaped as expected (not a list, an entry
    that is not an object, an id that is not a string) is skipped: the importer reports it when
    it reads it. Empty ids are skipped too: importers treat them as missing and make one up.
    """
    # (list, its path, next index): a stack rather than recursion, so any depth works
    stack: list[tuple[list[Any], str, int]] = [(value, path, 0)] if isinstance(value, list) else []
    while stack:
        items, here, start = stack.pop()
        for index in range(start, len(items)):
            item = items[index]
            if not isinstance(item, dict):
                continue
            raw = item.get("id")
            if isinstance(raw, str) and raw:
                yield raw, f"{here}[{index}].id"
            nested = item.get(children) if children is not None else None
            if isinstance(nested, list) and nested:
                stack.append((items, here, index + 1))  # the siblings after this subtree
                stack.append((nested, f"{here}[{index}].{children}", 0))
                break


def check_unique_ids(entries: Iterable[tuple[str, str]], source: str) -> None:
    """Raise a SpecError at the second use of an id, naming the first one too.

    ``entries`` are ``(id, JSON path)`` pairs of one namespace in document order; the message
    reads ``house.json: objects[3].id: duplicate id 'Chair|2|1' (also objects[1].id)``.
    """
    first: dict[str, str] = {}
    for raw, where in entries:
        if raw in first:
            raise SpecError(f"duplicate id {raw!r} (also {first[raw]})", where=f"{source}: {where}")
        first[raw] = where


class IdMap:
    """Hands out unique sanitised ids for one namespace, remembering raw -> new.

    :attr:`renamed` lists a warning for every id given by the input that had to take a suffix
    because its sanitised form was already handed out.
    """

    def __init__(self, fallback: str) -> None:
        self.fallback = fallback
        self.renamed: list[str] = []
        self._used: set[str] = set()
        self._by_raw: dict[str, str] = {}
        self._given: set[str] = set()

    def new(self, raw: str | None, where: str | None = None) -> str:
        """A fresh unique id for ``raw``, remembered for :meth:`lookup`.

        ``where`` is the JSON path of ``raw`` when the input gave it (rather than the importer
        making it up): a suffix added to such an id is recorded in :attr:`renamed`, and it wins
        :meth:`lookup` over a made-up id with the same text. Otherwise the first one wins.
        """
        base = sanitise(raw, self.fallback) if raw else self.fallback
        candidate = base
        counter = 2
        while candidate in self._used:
            suffix = f"_{counter}"
            candidate = base[: _MAX_LEN - len(suffix)] + suffix
            counter += 1
        self._used.add(candidate)
        if raw is not None and where is not None and candidate != base:
            why = (
                "the same id appears earlier"
                if raw in self._given
                else f"its holomj form {base!r} was already taken"
            )
            self.renamed.append(f"{where}: id {raw!r} renamed to {candidate!r} ({why})")
        if raw is not None:
            given_first = where is not None and raw not in self._given
            if raw not in self._by_raw or given_first:
                self._by_raw[raw] = candidate
            if where is not None:
                self._given.add(raw)
        return candidate

    def lookup(self, raw: str) -> str | None:
        """The id given to ``raw`` earlier, if any."""
        return self._by_raw.get(raw)
