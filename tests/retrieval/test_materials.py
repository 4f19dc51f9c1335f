"""Materials: the described built-in palette, text choice per surface, texture import (CLI)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from PIL import Image
from typer.testing import CliRunner

from holomj.cli import app
from holomj.errors import InputError, SpecError
from holomj.retrieval.materials import SURFACES, MaterialLibrary, choose_material, material_picker
from holomj.retrieval.texture_import import (
    MAX_TEXTURE_PX,
    guess_surfaces,
    is_auxiliary_map,
    texture_words,
)
from holomj.spec.materials import BUILTIN_MATERIALS

runner = CliRunner()


def test_every_builtin_is_described_with_valid_surfaces():
    table = json.loads(
        (Path(__file__).parents[2] / "holomj/data/material_descriptions.json").read_text()
    )
    described = {k for k in table if not k.startswith("_")}
    assert described == set(BUILTIN_MATERIALS)
    library = MaterialLibrary.load(Path("/nonexistent/materials"))
    assert len(library.entries) == len(BUILTIN_MATERIALS)
    for entry in library.entries:
        assert entry.builtin and entry.description and set(entry.surfaces) <= set(SURFACES)
    for surface in SURFACES:
        assert len(library.for_surface(surface)) >= 5
    assert library.get("glass").surfaces == ()  # never a room surface


@pytest.mark.parametrize(
    ("description", "surface", "expected"),
    [
        ("industrial concrete", "floor", "industrial_concrete"),
        ("brick red paint", "wall", "brick_red_paint"),
        ("terracotta tiles", "floor", "terracotta_tile"),
        ("dark slate", "floor", "dark_slate"),
        ("light grey carpet", "floor", "light_grey_carpet"),
        ("white paint", "wall", "white_paint"),
        ("white ceiling", "ceiling", "ceiling_default"),
        ("oak_floor", "floor", "oak_floor"),
        ("exposed brick", "wall", "brick"),
    ],
)
def test_choose_builtin_material(encoder, description, surface, expected):
    library = MaterialLibrary.load(Path("/nonexistent/materials"))
    name, material = choose_material(description, surface, library=library, encoder=encoder)
    assert name == expected
    assert material == BUILTIN_MATERIALS[expected]


def test_choice_respects_the_surface(encoder):
    library = MaterialLibrary.load(Path("/nonexistent/materials"))
    name, _ = choose_material("white paint", "floor", library=library, encoder=encoder)
    assert "floor" in library.get(name).surfaces and name != "white_paint"
    name, _ = choose_material("a soft carpet", "wall", library=library, encoder=encoder)
    assert "wall" in library.get(name).surfaces
    with pytest.raises(InputError, match="unknown surface 'roof'"):
        choose_material("tiles", "roof", library=library, encoder=encoder)


def test_texture_names_maps_and_surfaces():
    assert texture_words("libero_seamless_wood_planks_floor") == [
        "seamless",
        "wood",
        "planks",
        "floor",
    ]
    assert texture_words("ph_rosewood_veneer1_diff_1k") == ["rosewood", "veneer"]
    assert texture_words("rs_light-gray-floor-tile") == ["light", "gray", "floor", "tile"]
    assert texture_words("scenesim_white_marble_tile2") == ["white", "marble", "tile"]
    assert is_auxiliary_map("ph_rosewood_veneer1_nor_gl_1k")
    assert is_auxiliary_map("ph_wood_table_worn_rough_1k")
    assert not is_auxiliary_map("ph_wood_table_worn_diff_1k")
    assert guess_surfaces(["oak", "floorboard"]) == ["floor"]
    assert guess_surfaces(["white", "plaster"]) == ["wall"]
    assert guess_surfaces(["ceramic", "tile"]) == ["floor", "wall"]
    assert guess_surfaces(["light", "wood"]) == list(SURFACES)


@pytest.mark.slow
def test_import_shared_textures_through_the_cli(shared_assets, tmp_path, encoder):
    source = shared_assets / "textures"
    target = tmp_path / "materials"
    result = runner.invoke(
        app, ["materials", "import", str(source), "--materials", str(target), "--json"]
    )
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    images = [p for p in source.iterdir() if p.suffix.lower() in (".png", ".jpg")]
    maps = sorted(p.name for p in images if "_nor_" in p.name or "_rough_" in p.name)
    assert sorted(s["file"] for s in summary["skipped"]) == maps
    assert len(summary["added"]) == len(images) - len(maps)
    added = {a["name"]: a for a in summary["added"]}
    planks = added["seamless_wood_planks_floor"]
    assert planks["description"] == "seamless wood planks floor"
    assert planks["surfaces"] == ["floor"]
    assert added["white_plaster"]["surfaces"] == ["wall"]
    for item in summary["added"]:
        png = Path(item["texture"])
        assert png.is_absolute() and png.parent == target
        with Image.open(png) as img:
            assert img.format == "PNG" and max(img.size) <= MAX_TEXTURE_PX
    assert "rosewood_veneer" in added  # a JPG, now a PNG

    listed = runner.invoke(app, ["materials", "list", "--materials", str(target), "--json"])
    assert listed.exit_code == 0
    rows = {r["name"]: r for r in json.loads(listed.stdout)}
    assert set(added) <= set(rows) and set(BUILTIN_MATERIALS) <= set(rows)

    library = MaterialLibrary.load(target)
    name, material = choose_material("wood plank floor", "floor", library=library, encoder=encoder)
    assert not library.get(name).builtin
    assert {"wood", "plank", "planks", "floorboard"} & set(name.split("_")), name
    assert material.texture is not None and Path(material.texture).is_file()
    pick = material_picker(encoder=encoder, materials=target)
    assert pick("wood plank floor", "floor") == (name, material)

    again = runner.invoke(
        app, ["materials", "import", str(source), "--materials", str(target), "--json"]
    )
    assert again.exit_code == 0
    assert sorted(json.loads(again.stdout)["replaced"]) == sorted(added)
    assert len(MaterialLibrary.load(target).entries) == len(library.entries)


def _small_folder(tmp_path: Path, shared_assets: Path) -> Path:
    folder = tmp_path / "textures"
    folder.mkdir()
    for name in ("rs_dark-wood.png", "libero_stucco_wall.png", "ph_wood_table_worn_diff_1k.jpg"):
        shutil.copy(shared_assets / "textures" / name, folder / name)
    return folder


def test_import_options_and_jpg_conversion(shared_assets, tmp_path):
    folder = _small_folder(tmp_path, shared_assets)
    target = tmp_path / "materials"
    result = runner.invoke(
        app,
        ["materials", "import", str(folder), "--materials", str(target), "--surface", "ceiling"]
        + ["--texture-size", "2.5", "--json"],
    )
    assert result.exit_code == 0, result.output
    library = MaterialLibrary.load(target)
    worn = library.get("wood_table_worn")
    assert worn.surfaces == ("ceiling",) and worn.material.texture_size_m == 2.5
    assert sorted(p.name for p in target.iterdir()) == [
        "dark_wood.png",
        "materials.json",
        "stucco_wall.png",
        "wood_table_worn.png",
    ]


def test_bad_input_exits_2_and_writes_nothing(shared_assets, tmp_path):
    target = tmp_path / "materials"
    missing = runner.invoke(
        app, ["materials", "import", str(tmp_path / "nope"), "--materials", str(target)]
    )
    assert missing.exit_code == 2 and "texture folder not found" in missing.output
    assert len(missing.output.strip().splitlines()) == 1
    assert not target.exists()

    only_maps = tmp_path / "maps"
    only_maps.mkdir()
    shutil.copy(shared_assets / "textures" / "ph_wood_table_worn_rough_1k.png", only_maps)
    result = runner.invoke(app, ["materials", "import", str(only_maps), "--materials", str(target)])
    assert result.exit_code == 2 and "no colour texture images" in result.output
    assert not target.exists()

    folder = _small_folder(tmp_path, shared_assets)
    first = runner.invoke(app, ["materials", "import", str(folder), "--materials", str(target)])
    assert first.exit_code == 0, first.output
    before = {p.name: p.read_bytes() for p in target.iterdir()}
    broken = tmp_path / "broken"
    shutil.copytree(folder, broken)
    (broken / "cracked_tile.png").write_text("not a png")
    result = runner.invoke(app, ["materials", "import", str(broken), "--materials", str(target)])
    assert result.exit_code == 2
    assert "cannot read image" in result.output and "cracked_tile.png" in result.output
    assert {p.name: p.read_bytes() for p in target.iterdir()} == before
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".materials")] == []

    bad_surface = runner.invoke(
        app, ["materials", "import", str(folder), "--materials", str(target), "--surface", "roof"]
    )
    assert bad_surface.exit_code == 2 and "unknown surface 'roof'" in bad_surface.output


def test_broken_materials_index_is_a_spec_error(tmp_path):
    target = tmp_path / "materials"
    target.mkdir()
    (target / "materials.json").write_text(json.dumps({"materials": {"x": {"surfaces": []}}}))
    with pytest.raises(SpecError, match=r"materials\.json"):
        MaterialLibrary.load(target)
    result = runner.invoke(app, ["materials", "list", "--materials", str(target)])
    assert result.exit_code == 2
