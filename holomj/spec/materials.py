"""Materials: the data type and the built-in palette every scene may use by name."""

from __future__ import annotations

import json
from importlib import resources
from typing import Annotated

from pydantic import Field

from holomj.spec.base import FrozenModel, PositiveFloat, Rgba


class Material(FrozenModel):
    """A surface look: a colour and optionally a tiling texture image."""

    rgba: Rgba = (0.8, 0.8, 0.8, 1.0)
    texture: str | None = Field(
        default=None,
        description="PNG file, relative to the scene file's folder (or absolute while importing).",
    )
    texture_size_m: PositiveFloat = Field(default=1.0, description="World size of one tile.")
    specular: Annotated[float, Field(ge=0.0, le=1.0)] = 0.2
    shininess: Annotated[float, Field(ge=0.0, le=1.0)] = 0.2
    reflectance: Annotated[float, Field(ge=0.0, le=1.0)] = 0.0


def _load_builtin() -> dict[str, Material]:
    text = resources.files("holomj.data").joinpath("materials.json").read_text(encoding="utf-8")
    return {name: Material.model_validate(value) for name, value in json.loads(text).items()}


BUILTIN_MATERIALS: dict[str, Material] = _load_builtin()
