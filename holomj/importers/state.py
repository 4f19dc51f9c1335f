"""What every importer keeps while it reads one file: ids, materials, warnings, substitutions."""

from __future__ import annotations

from collections.abc import Iterable
from itertools import chain
from typing import Any

from holomj.errors import SpecError
from holomj.importers.common import finish_scene
from holomj.importers.ids import IdMap, check_unique_ids, listed_ids
from holomj.importers.jsonpath import Node
from holomj.importers.materials import MaterialResolver
from holomj.importers.result import ImportResult, Substitution
from holomj.library.store import AssetLibrary
from holomj.spec.scene import Room
from holomj.spec.walls import Wall, derive_walls


class ImportState:
    """Shared state and the shared last steps of the importers."""

    def __init__(self, data: Any, library: AssetLibrary, source: str) -> None:
        self.root = Node(data, source).dict()
        self.library = library
        self.source = source
        self.materials = MaterialResolver()
        self.warnings: list[str] = []
        self.substitutions: list[Substitution] = []
        self.merged: list[dict[str, str]] = []  # objects left out as part of their parent
        self.room_ids = IdMap("room")
        self.opening_ids = IdMap("opening")
        self.object_ids = IdMap("object")
        self.light_ids = IdMap("light")
        self.rooms: list[Room] = []

    def derive_walls(self) -> list[Wall]:
        """Walls of the rooms read so far; geometry errors name the source file."""
        try:
            return derive_walls(self.rooms)
        except SpecError as err:
            raise err.located(f"{self.source}: rooms") from None

    def check_ids(self, namespaces: Iterable[Iterable[tuple[str, str]]]) -> None:
        """Reject an id used twice in one namespace (each an iterable of ``(id, JSON path)``
        in document order), naming both places; see :func:`check_unique_ids`."""
        for entries in namespaces:
            check_unique_ids(entries, self.source)

    def check_scene_ids(self, data: dict[str, Any], children: str | None = None) -> None:
        """Reject ids used twice among the rooms, the openings (doors and windows share
        holomj's namespace) or the objects (with ``children``: nested ones included) of the
        input's top-level ``data``, naming both places."""
        self.check_ids(
            [
                listed_ids(data.get("rooms"), "rooms"),
                chain(
                    listed_ids(data.get("doors"), "doors"),
                    listed_ids(data.get("windows"), "windows"),
                ),
                listed_ids(data.get("objects"), "objects", children=children),
            ]
        )

    def result(self, fields: dict[str, Any], fmt: str) -> ImportResult:
        """Validate the scene built from ``fields`` and wrap it with this import's report."""
        scene = finish_scene(fields, self.library, self.source)
        renamed = [
            warning
            for ids in (self.room_ids, self.opening_ids, self.object_ids, self.light_ids)
            for warning in ids.renamed
        ]
        return ImportResult(
            scene=scene,
            format=fmt,
            substitutions=self.substitutions,
            warnings=self.materials.warnings + self.warnings + renamed,
            merged=self.merged,
        )
