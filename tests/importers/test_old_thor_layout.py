"""An AI2-THOR layout from before ProcTHOR is refused in one line naming what is missing."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from holomj.errors import FormatError
from holomj.importers.detect import detect_format

ITHOR_SCENE = {
    "sceneName": "FloorPlan1",
    "objects": [{"objectId": "Apple|+1.0|+0.9|+1.0", "objectType": "Apple", "position": {}}],
}


def test_an_ithor_scene_names_the_missing_rooms() -> None:
    with pytest.raises(FormatError) as caught:
        detect_format(ITHOR_SCENE, "old.json")
    assert "an AI2-THOR layout without 'rooms'" in caught.value.one_line()


def test_rooms_without_floor_polygons_are_named() -> None:
    house = {"rooms": [{"id": "r"}], "walls": [], "objects": []}
    with pytest.raises(FormatError, match=r"without 'rooms\[\]\.floorPolygon'"):
        detect_format(house, "old.json")


def test_the_cli_refuses_it_with_exit_code_2(tmp_path: Path) -> None:
    path = tmp_path / "old.json"
    path.write_text(json.dumps(ITHOR_SCENE))
    result = CliRunner().invoke(app, ["compile", str(path), "-o", str(tmp_path / "out")])
    assert result.exit_code == 2
    assert "AI2-THOR layout without 'rooms'" in " ".join(result.output.split())
    assert not (tmp_path / "out").exists()
