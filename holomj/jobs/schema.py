"""The schema job (``holomj schema``): the JSON Schema of a holomj data format, written out."""

from __future__ import annotations

from pathlib import Path

from holomj.jobs.folder import write_json_file


def write_schema(kind: str = "scene", out: Path | str = "-") -> None:
    """Write the JSON Schema of ``kind`` (scene, asset, library, report, plan or task) to ``out``
    ('-': standard output); an unknown kind is an InputError listing the known ones."""
    from holomj.spec.schema import json_schema

    write_json_file(Path(out), json_schema(kind))
