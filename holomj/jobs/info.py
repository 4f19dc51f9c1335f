"""The info job (``holomj info OUT``): what a scene folder holds."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from holomj.errors import FormatError
from holomj.file_names import SCENE_JSON, SCENE_XML
from holomj.formats.summaries import model_summary, scene_summary
from holomj.mjcf.loading import load_model_file
from holomj.spec.base import read_json, validate_model
from holomj.spec.scene import SceneSpec


def folder_summary(out: Path) -> dict[str, Any]:
    """Summary of an exported folder: its scene.json and the model loaded from its scene.xml.

    ``lights`` counts the lights of the compiled model, which has a sun and ceiling lights where
    scene.json lists none."""
    out = Path(out)
    if not out.is_dir():
        raise FormatError(
            "not a folder (expected a folder written by 'holomj compile')", where=str(out)
        )
    scene_path = out / SCENE_JSON
    scene = validate_model(SceneSpec, read_json(scene_path), str(scene_path))
    model = load_model_file(out / SCENE_XML)
    summary = model_summary(model)
    return {
        "folder": str(out),
        **scene_summary(scene),
        "lights": summary["lights"],
        "model": summary,
    }
