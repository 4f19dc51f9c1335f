"""Sidecar files override metadata; bad sidecars name the file and the field."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from asset_pipeline import physical
from asset_pipeline.importer import ImportOptions, import_asset
from holomj.errors import FormatError, SpecError
from tests.asset_pipeline.import_helpers import LOW, box_obj


@pytest.fixture
def crate(tmp_path: Path) -> Path:
    path = tmp_path / "crate.obj"
    path.write_text(box_obj(0.4, 0.3, 0.25))
    return path


def test_defaults_without_sidecar(crate: Path) -> None:
    imported = import_asset(crate, "crate", ImportOptions(coacd=LOW))
    meta = imported.bundle.meta
    assert meta.category == "object"  # "crate" is not in the table
    assert meta.description == "an object"
    assert meta.placement == ["object"]
    assert meta.license is None
    # An unknown thing of unknown make-up: a 2 cm skin of 500 kg/m3 under its surface.
    info = physical.category_info("object")
    area = 2 * (0.4 * 0.3 + 0.4 * 0.25 + 0.3 * 0.25)
    assert (info.density_kg_m3, info.wall_m) == (500.0, 0.02)
    assert meta.mass == pytest.approx(500.0 * area * 0.02, rel=1e-3)
    assert imported.report["physical"]["mass_derivation"]["bodies_hollowed_to_wall"] == 1
    assert imported.report["decomposition"]["method"] == "convex_bodies"
    assert imported.report["source"]["sidecar"] is None


def test_json_sidecar_next_to_the_file_overrides_fields(crate: Path) -> None:
    sidecar = crate.with_name("crate.holomj.json")
    sidecar.write_text(
        json.dumps(
            {
                "category": "box",
                "friction": 1.2,
                "density_kg_m3": 100.0,
                "license": "CC-BY-4.0",
                "attribution": "Jane Doe",
                "placement": ["floor", "object"],
            }
        )
    )
    imported = import_asset(crate, "crate", ImportOptions(coacd=LOW))
    meta = imported.bundle.meta
    assert meta.category == "box" and meta.description == "a box"
    assert meta.friction == 1.2
    assert meta.placement == ["floor", "object"]
    assert meta.license == "CC-BY-4.0" and meta.attribution == "Jane Doe"
    assert meta.mass == pytest.approx(100.0 * 0.4 * 0.3 * 0.25, rel=1e-3)
    assert imported.report["source"]["sidecar"] == str(sidecar)
    # Explicit options win over the sidecar.
    chosen = import_asset(crate, "crate", ImportOptions(category="book", mass_kg=2.0, coacd=LOW))
    assert chosen.bundle.meta.category == "book" and chosen.bundle.meta.mass == 2.0


def test_yaml_sidecar(crate: Path, tmp_path: Path) -> None:
    pytest.importorskip("yaml")
    sidecar = tmp_path / "meta.yaml"
    sidecar.write_text("description: a wooden crate\nmass_kg: 3.5\nsource: my scan\n")
    imported = import_asset(crate, "crate", ImportOptions(sidecar=sidecar, coacd=LOW))
    meta = imported.bundle.meta
    assert (meta.description, meta.mass, meta.source) == ("a wooden crate", 3.5, "my scan")


@pytest.mark.parametrize(
    ("text", "error", "field"),
    [
        ('{"friction": 9}', SpecError, "friction"),
        ('{"colour": "red"}', SpecError, "colour"),
        ('{"density_kg_m3": "heavy"}', SpecError, "density_kg_m3"),
        ('{"placement": ["roof"]}', SpecError, "placement"),
        ("[1, 2]", SpecError, ""),
        ("{not json", FormatError, ""),
    ],
)
def test_bad_sidecar_names_file_and_field(
    crate: Path, tmp_path: Path, text: str, error: type, field: str
) -> None:
    sidecar = tmp_path / "bad.holomj.json"
    sidecar.write_text(text)
    with pytest.raises(error) as info:
        import_asset(crate, "crate", ImportOptions(sidecar=sidecar, coacd=LOW))
    message = str(info.value)
    assert str(sidecar) in message and field in message and "\n" not in message


def test_bad_yaml_sidecar(crate: Path, tmp_path: Path) -> None:
    pytest.importorskip("yaml")
    sidecar = tmp_path / "bad.yaml"
    sidecar.write_text("friction: [unclosed\n")
    with pytest.raises(FormatError, match="invalid YAML") as info:
        import_asset(crate, "crate", ImportOptions(sidecar=sidecar, coacd=LOW))
    assert str(sidecar) in str(info.value)
