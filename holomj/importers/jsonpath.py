"""Typed, path-aware reading of untrusted JSON: every failure names the file and the JSON path.

Importers are tolerant of extra fields and strict about the ones they need. A bad value raises
:class:`~holomj.errors.FormatError` with a location such as
``house.json: rooms[1].floorPolygon[2].x`` and a message such as ``expected a number``.
"""

from __future__ import annotations

import math
from typing import Any

from holomj.errors import FormatError

_MISSING = object()


class Node:
    """A JSON value together with the file it came from and its path inside that file."""

    __slots__ = ("path", "source", "value")

    def __init__(self, value: Any, source: str, path: str = "") -> None:
        self.value = value
        self.source = source
        self.path = path

    # -- locations -------------------------------------------------------------------------
    def where(self) -> str:
        """``source: path`` (or just the source at the root)."""
        return f"{self.source}: {self.path}" if self.path else self.source

    def error(self, what: str, fix: str | None = None) -> FormatError:
        """A FormatError located at this node."""
        return FormatError(what, where=self.where(), fix=fix)

    def _child_path(self, key: str | int) -> str:
        if isinstance(key, int):
            return f"{self.path}[{key}]"
        return f"{self.path}.{key}" if self.path else key

    # -- structure -------------------------------------------------------------------------
    def is_dict(self) -> bool:
        """True if the value is a JSON object."""
        return isinstance(self.value, dict)

    def dict(self) -> Node:
        """This node, checked to be a JSON object."""
        if not isinstance(self.value, dict):
            raise self.error(f"expected an object, got {_kind(self.value)}")
        return self

    def has(self, key: str) -> bool:
        """True if this node is an object with ``key`` set to something other than null."""
        return isinstance(self.value, dict) and self.value.get(key) is not None

    def get(self, key: str) -> Node:
        """The required member ``key`` of this object."""
        self.dict()
        if key not in self.value or self.value[key] is None:
            raise self.error(f"missing required field {key!r}")
        return Node(self.value[key], self.source, self._child_path(key))

    def opt(self, key: str) -> Node | None:
        """The member ``key`` if present and not null, else None."""
        self.dict()
        value = self.value.get(key)
        if value is None:
            return None
        return Node(value, self.source, self._child_path(key))

    def items(self) -> list[Node]:
        """The elements of this array."""
        if not isinstance(self.value, list):
            raise self.error(f"expected a list, got {_kind(self.value)}")
        return [Node(v, self.source, self._child_path(i)) for i, v in enumerate(self.value)]

    # -- scalars ---------------------------------------------------------------------------
    def number(self, *, limit: float = 1e6) -> float:
        """A finite number with magnitude at most ``limit``."""
        value = self.value
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.error(f"expected a number, got {_kind(value)}")
        try:
            number = float(value)
        except OverflowError:
            raise self.error("number is too large") from None
        if not math.isfinite(number):
            raise self.error("expected a finite number")
        if abs(number) > limit:
            raise self.error(f"number {number:g} is out of range (|x| <= {limit:g})")
        return number

    def string(self) -> str:
        """A string."""
        if not isinstance(self.value, str):
            raise self.error(f"expected a string, got {_kind(self.value)}")
        return self.value

    def boolean(self) -> bool:
        """A boolean."""
        if not isinstance(self.value, bool):
            raise self.error(f"expected true or false, got {_kind(self.value)}")
        return self.value

    # -- helpers for common shapes ---------------------------------------------------------
    def num(self, key: str, default: Any = _MISSING, *, limit: float = 1e6) -> float:
        """Member ``key`` as a number; ``default`` when absent (required if no default)."""
        node = self.opt(key)
        if node is None:
            if default is _MISSING:
                raise self.error(f"missing required field {key!r}")
            return default
        return node.number(limit=limit)

    def str_(self, key: str, default: Any = _MISSING) -> str:
        """Member ``key`` as a string; ``default`` when absent (required if no default)."""
        node = self.opt(key)
        if node is None:
            if default is _MISSING:
                raise self.error(f"missing required field {key!r}")
            return default
        return node.string()

    def bool_(self, key: str, default: bool) -> bool:
        """Member ``key`` as a boolean, ``default`` when absent."""
        node = self.opt(key)
        return default if node is None else node.boolean()

    def xyz(self) -> tuple[float, float, float]:
        """An ``{"x", "y", "z"}`` object; all three components are required."""
        self.dict()
        return (self.num("x"), self.num("y"), self.num("z"))

    def vector(self, length: int, *, limit: float = 1e6) -> tuple[float, ...]:
        """A list of exactly ``length`` numbers."""
        items = self.items()
        if len(items) != length:
            raise self.error(f"expected {length} numbers, got {len(items)}")
        return tuple(item.number(limit=limit) for item in items)

    def vector3(self, *, limit: float = 1e6) -> tuple[float, float, float]:
        """A list of exactly three numbers."""
        x, y, z = self.vector(3, limit=limit)
        return (x, y, z)


def _kind(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, (int, float)):
        return "a number"
    if isinstance(value, str):
        return "a string"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "an object"
    return type(value).__name__
