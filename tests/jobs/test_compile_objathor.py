"""``holomj compile HOUSE --objathor DIR``: the Objaverse assets a Holodeck house names by uid
are imported from DIR first, so the house uses the real meshes (no stand-ins)."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from holomj.cli import app
from tests.asset_pipeline.objathor_data import BOX_UID, CLOCK_UID, DESK_UID, build_objathor_dir
from tests.cli.test_objathor_cli import holodeck_house


def test_objathor_folder_gives_the_house_its_real_meshes(
    tmp_path: Path, shared_assets: Path
) -> None:
    build_objathor_dir(tmp_path / "dir", shared_assets)
    # the house is written against a library holding the same assets (for their sizes)
    runner = CliRunner()
    sizes = tmp_path / "sizes"
    imported = runner.invoke(
        app, ["assets", "import-objathor", str(tmp_path / "dir"), "--library", str(sizes),
              "--no-thumbnails", "--json"],
    )  # fmt: skip
    assert imported.exit_code == 0, imported.output
    house = tmp_path / "house.json"
    house.write_text(json.dumps(holodeck_house(sizes)))
    out = tmp_path / "out"
    result = runner.invoke(
        app,
        ["compile", str(house), "-o", str(out), "--library", str(tmp_path / "lib"),
         "--objathor", str(tmp_path / "dir"), "--check-seconds", "0", "--json"],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["substitutions"] == []
    assert "--objathor: 3 of the house's 3 asset ids imported" in report["warnings"][0]
    scene = json.loads((out / "scene.json").read_text())
    assert {o["asset"] for o in scene["objects"]} == {DESK_UID, BOX_UID, CLOCK_UID}
