"""JSON Schemas of the holomj data formats (``holomj schema``)."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel

from holomj.errors import InputError
from holomj.spec.assets import AssetMeta, LibraryIndex
from holomj.spec.plan import ScenePlan
from holomj.spec.report import StabilityReport
from holomj.spec.scene import SceneSpec
from holomj.spec.tasks import TaskSet

SCHEMAS: dict[str, type[BaseModel]] = {
    "scene": SceneSpec,
    "asset": AssetMeta,
    "library": LibraryIndex,
    "report": StabilityReport,
    "plan": ScenePlan,
    "task": TaskSet,
}


def json_schema(kind: str = "scene") -> dict[str, Any]:
    """The JSON Schema of ``kind`` (scene, asset, library, report, plan or task)."""
    try:
        model = SCHEMAS[kind]
    except KeyError:
        raise InputError(
            f"unknown schema {kind!r}", fix=f"use one of: {', '.join(SCHEMAS)}"
        ) from None
    schema = model.model_json_schema()
    version = model.model_fields["schema_version"].default
    schema["$comment"] = f"holomj {kind} format, schema_version {version}"
    return schema
