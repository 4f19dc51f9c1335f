"""The info job (``holomj info OUT``): what a scene folder holds."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.errors import FormatError
from holomj.file_names import SCENE_JSON, SCENE_XML
from holomj.formats.summaries import ModelSummary, SceneSummary, model_summary, scene_summary
from holomj.mjcf.loading import load_model_file
from holomj.spec.base import read_json, validate_model
from holomj.spec.scene import SceneSpec


@dataclass(frozen=True)
class FolderSummary:
    """What a scene folder holds: its scene (rooms, openings, objects) and its compiled model.

    ``lights`` counts the lights of the compiled model, which has a sun and ceiling lights where
    scene.json lists none."""

    folder: str
    scene: SceneSummary
    model: ModelSummary

    @property
    def lights(self) -> int:
        """The lights the scene is lit by (the compiled model's)."""
        return self.model.lights

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form: the folder, the scene's fields, the lights and the model."""
        return {
            "folder": self.folder,
            **self.scene.to_dict(),
            "lights": self.lights,
            "model": self.model.to_dict(),
        }


def folder_summary(out: Path) -> FolderSummary:
    """Summary of an exported folder: its scene.json and the model loaded from its scene.xml."""
    out = Path(out)
    if not out.is_dir():
        raise FormatError(
            "not a folder (expected a folder written by 'holomj compile')", where=str(out)
        )
    scene_path = out / SCENE_JSON
    scene = validate_model(SceneSpec, read_json(scene_path), str(scene_path))
    model = load_model_file(out / SCENE_XML)
    return FolderSummary(str(out), scene_summary(scene), model_summary(model))
