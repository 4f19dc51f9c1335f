"""A small XML tree with line numbers (the stdlib's expat parser), and readers of number
attributes whose errors name the element and its line (URDF and MJCF files)."""

from __future__ import annotations

import math
import re
import xml.parsers.expat
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from holomj.errors import FormatError

MAX_FILE_BYTES = 50_000_000


@dataclass
class XmlNode:
    """An XML element: tag, attributes, children and the line it starts on."""

    tag: str
    attrib: dict[str, str]
    line: int
    children: list[XmlNode] = field(default_factory=list)

    def find(self, tag: str) -> XmlNode | None:
        """The first child with ``tag``."""
        return next((c for c in self.children if c.tag == tag), None)

    def findall(self, tag: str) -> list[XmlNode]:
        """Every child with ``tag``."""
        return [c for c in self.children if c.tag == tag]

    def iter(self):
        """This element and all below it, depth first."""
        yield self
        for child in self.children:
            yield from child.iter()


def parse_xml(data: bytes | str, where: str) -> XmlNode:
    """The root element of ``data``; FormatError for anything that is not plain XML.

    DOCTYPE declarations (and with them entity definitions) are refused.
    """
    parser = xml.parsers.expat.ParserCreate()
    stack: list[XmlNode] = []
    roots: list[XmlNode] = []

    def start(tag: str, attrib: dict[str, str]) -> None:
        node = XmlNode(tag, dict(attrib), parser.CurrentLineNumber)
        if stack:
            stack[-1].children.append(node)
        else:
            roots.append(node)
        stack.append(node)

    def end(tag: str) -> None:
        stack.pop()

    def doctype(*args: object) -> None:
        raise FormatError("a DOCTYPE declaration is not allowed", where=where)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.StartDoctypeDeclHandler = doctype
    try:
        parser.Parse(data, True)
    except xml.parsers.expat.ExpatError as err:
        reason = xml.parsers.expat.ErrorString(err.code)
        raise FormatError(
            f"not well-formed XML: {reason} at line {err.lineno}", where=where
        ) from None
    if not roots:
        raise FormatError("the file holds no XML element", where=where)
    return roots[0]


def read_text(path: Path) -> bytes:
    """The bytes of a description file; FormatError when missing, empty or huge."""
    where = str(path)
    if not path.is_file():
        raise FormatError("file not found", where=where, fix="check the path")
    size = path.stat().st_size
    if size == 0:
        raise FormatError("the file is empty", where=where)
    if size > MAX_FILE_BYTES:
        raise FormatError(f"the file has {size} bytes, more than {MAX_FILE_BYTES}", where=where)
    return path.read_bytes()


def origin_transform(node: XmlNode | None, what: str, where: str) -> np.ndarray:
    """The 4x4 transform of an ``<origin xyz rpy>`` (identity when absent)."""
    transform = np.eye(4)
    if node is None:
        return transform
    what = f"{what} <origin> (line {node.line})"
    xyz = attr_vec3(node, "xyz", what, where, default=(0.0, 0.0, 0.0))
    rpy = attr_vec3(node, "rpy", what, where, default=(0.0, 0.0, 0.0))
    transform[:3, :3] = rpy_matrix(rpy)
    transform[:3, 3] = xyz
    return transform


def rpy_matrix(rpy: tuple[float, float, float]) -> np.ndarray:
    """URDF's roll-pitch-yaw: ``Rz(yaw) @ Ry(pitch) @ Rx(roll)``."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = (
        math.cos(r),
        math.sin(r),
        math.cos(p),
        math.sin(p),
        math.cos(y),
        math.sin(y),
    )
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def attr_floats(
    node: XmlNode,
    key: str,
    count: int,
    what: str,
    where: str,
    default: tuple[float, ...] | None = None,
) -> tuple[float, ...]:
    """The ``count`` numbers of attribute ``key`` of ``node`` (``default`` when absent; a
    FormatError naming ``what``, the element and its line when missing or not numbers)."""
    text = node.attrib.get(key)
    if text is None:
        if default is None:
            raise FormatError(f"{what}: <{node.tag}> (line {node.line}) has no {key}", where=where)
        return default
    items = text.split()
    if len(items) != count or not all(_NUMBER.match(item) for item in items):
        raise FormatError(
            f"{what}: {key}={text[:40]!r} of <{node.tag}> (line {node.line}) is not "
            f"{count} number{'s' if count > 1 else ''}",
            where=where,
        )
    values = tuple(float(item) for item in items)
    if not all(math.isfinite(v) for v in values):
        raise FormatError(f"{what}: {key} of <{node.tag}> is not finite", where=where)
    return values


def attr_vec3(
    node: XmlNode,
    key: str,
    what: str,
    where: str,
    default: tuple[float, float, float] | None = None,
) -> tuple[float, float, float]:
    """The three numbers of attribute ``key`` of ``node`` (see :func:`attr_floats`)."""
    x, y, z = attr_floats(node, key, 3, what, where, default)
    return (x, y, z)


def attr_float(
    node: XmlNode, key: str, what: str, where: str, default: float | None = None
) -> float:
    """The one number of attribute ``key`` of ``node`` (see :func:`attr_floats`)."""
    return attr_floats(node, key, 1, what, where, None if default is None else (default,))[0]


def positive_sizes(values: tuple[float, ...], what: str, where: str) -> tuple[float, ...]:
    """``values``, or a FormatError naming ``what`` when one is not positive."""
    if any(v <= 0 for v in values):
        raise FormatError(f"{what}: sizes must be positive, got {values}", where=where)
    return values
