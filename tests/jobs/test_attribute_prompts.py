"""The attribute prompts of issue 15 (``scripts/eval/prompts_attributes.jsonl``), end to end
through the synthesis path: parsed, synthesised into a library, then checked on the written
asset itself: the visual materials' colours (rgba close to the named colour or material), which
parts carry a part's colour (legs low, a top on top, handles in front...), and the geometry of
shapes (a round footprint is a circle, an oval an ellipse, a square has corners, an L-shaped
desk leaves its front corner empty).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from asset_pipeline.library_writer import write_library
from asset_pipeline.procedural.attributes import MATERIALS, SECONDARY, colour_rgb
from holomj.jobs.synthesis import parse_attributes, synthesise

PROMPTS = Path(__file__).resolve().parents[2] / "scripts" / "eval" / "prompts_attributes.jsonl"
SEEDS = (0, 1)
RGB_TOLERANCE = 0.011  # colours are written to 4 decimals


def _prompts() -> list[dict[str, Any]]:
    return [json.loads(line) for line in PROMPTS.read_text().splitlines() if line.strip()]


def test_the_prompt_set_is_large_and_varied() -> None:
    prompts = _prompts()
    assert len(prompts) >= 20
    keys = {k for p in prompts for k in p["expect"]}
    assert {"colour", "material", "shape"} <= keys
    assert len({k for k in keys if "." in k}) >= 8  # part requests of many kinds
    assert {p["expect"].get("shape") for p in prompts} >= {"round", "oval", "square", "l-shaped"}


@pytest.fixture(scope="module")
def library(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return write_library(tmp_path_factory.mktemp("attribute_prompts") / "lib", "prompts", [])


class Visual:
    """One visual mesh of a written asset: its material's look and its geometry."""

    def __init__(self, folder: Path, entry: dict[str, Any]) -> None:
        self.name = entry["mesh"].removesuffix(".obj")
        self.rgba = tuple(entry.get("rgba", (0.7, 0.7, 0.7, 1.0)))
        self.specular = entry.get("specular", 0.3)
        self.texture = entry.get("texture")
        vertices, faces = [], []
        for line in (folder / entry["mesh"]).read_text().splitlines():
            tokens = line.split()
            if tokens and tokens[0] == "v":
                vertices.append([float(t) for t in tokens[1:4]])
            elif tokens and tokens[0] == "f":
                faces.append([int(t.split("/")[0]) - 1 for t in tokens[1:4]])
        self.vertices = np.array(vertices)
        tri = self.vertices[np.array(faces)]
        cross = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        self.area = float(0.5 * np.linalg.norm(cross, axis=1).sum())
        self.low, self.high = self.vertices.min(axis=0), self.vertices.max(axis=0)


def _expected_look(colour: str | None, material: str | None) -> tuple[np.ndarray, float | None]:
    """The rgb a request should show and the specular its material brings (None: kept)."""
    if colour is not None:
        rgb = np.array(colour_rgb(colour))
    else:
        assert material is not None
        rgb = np.array(MATERIALS[material].rgba[:3])
    return rgb, (MATERIALS[material].specular if material else None)


def _check_look(visual: Visual, colour: str | None, material: str | None, what: str) -> None:
    rgb, specular = _expected_look(colour, material)
    if visual.texture is not None:  # a textured material: its tint averages to the colour
        from asset_pipeline.procedural.textures import PATTERNS, texture_file, tinted

        pattern = {texture_file(p): p for p in PATTERNS}[visual.texture]
        rgb = np.array(tinted((*rgb, 1.0), pattern)[:3])
    assert np.abs(np.array(visual.rgba[:3]) - rgb).max() <= RGB_TOLERANCE, (what, visual.name)
    if specular is not None:
        assert visual.specular == pytest.approx(specular, abs=1e-4), (what, visual.name)
    if material == "glass":
        assert visual.rgba[3] < 1.0, (what, visual.name)


# Where a part's colour must be, as a test on the part's bounds (low, high) within the asset's
# (size x, y, z; the asset is centred in x and y, its bottom at z = 0).
PLACES = {
    "legs": lambda lo, hi, s: lo[2] < 0.01 and hi[2] < s[2] - 0.005,
    "base": lambda lo, hi, s: lo[2] < 0.01 and hi[2] < 0.5 * s[2],
    "top": lambda lo, hi, s: hi[2] > s[2] - 0.002 and lo[2] > 0.5 * s[2],
    "handles": lambda lo, hi, s: hi[0] > 0.5 * s[0] - 0.002,
    "drawers": lambda lo, hi, s: lo[0] > 0.25 * s[0] and hi[2] < s[2],
    "seat": lambda lo, hi, s: lo[2] > 0.15 * s[2] and hi[2] < 0.7 * s[2],
    "cushions": lambda lo, hi, s: lo[2] > 0.05 * s[2] and hi[2] < 0.7 * s[2],
    "shade": lambda lo, hi, s: lo[2] > 0.5 * s[2] and hi[2] > s[2] - 0.002,
    "headboard": lambda lo, hi, s: lo[0] < -0.5 * s[0] + 0.002 and hi[2] > s[2] - 0.002,
    "bedding": lambda lo, hi, s: lo[2] > 0.1 * s[2],
}


def _check_shape(shape: str, visuals: list[Visual], meta: dict[str, Any]) -> None:
    x, y, z = meta["size"]
    points = np.concatenate([v.vertices for v in visuals])
    if shape == "round" and meta["category"] == "mirror":  # a disc facing +X
        assert y == pytest.approx(z, abs=1e-3)
        radius = np.hypot(points[:, 1], points[:, 2] - 0.5 * z)
        assert radius.max() <= 0.5 * z + 1e-3
        return
    top = points[points[:, 2] > z - 0.005]
    if shape in ("round", "square"):
        assert x == pytest.approx(y, abs=1e-3)
    if shape == "round":
        radius = np.hypot(top[:, 0], top[:, 1])
        assert radius.max() == pytest.approx(0.5 * x, abs=2e-3)
        corner = (np.abs(points[:, 0]) > 0.4 * x) & (np.abs(points[:, 1]) > 0.4 * y)
        assert not corner.any(), "a round footprint has nothing in its bounding box's corners"
    elif shape == "oval":
        a, b = 0.5 * x, 0.5 * y
        assert abs(a - b) > 0.05
        assert ((top[:, 0] / a) ** 2 + (top[:, 1] / b) ** 2).max() <= 1.0 + 2e-3
        assert not ((np.abs(points[:, 0]) > 0.4 * x) & (np.abs(points[:, 1]) > 0.4 * y)).any()
    elif shape == "square":
        for sx in (-1, 1):
            for sy in (-1, 1):
                near = np.hypot(top[:, 0] - sx * 0.5 * x, top[:, 1] - sy * 0.5 * y)
                assert near.min() < 0.005, "a square top reaches its four corners"
    elif shape == "l-shaped":
        surfaces = [s for s in meta["surfaces"] if s["height"] > z - 0.01]
        assert len(surfaces) == 2
        share = sum(s["area_m2"] for s in surfaces) / (x * y)
        assert 0.4 < share < 0.9
        front_left = (points[:, 0] > 0.5 * x - 0.1) & (points[:, 1] < -0.5 * y + 0.1)
        assert not front_left.any(), "the front corner away from the return is empty"
    else:  # pragma: no cover - the prompt set names only the shapes above
        raise AssertionError(shape)


@pytest.mark.parametrize("prompt", _prompts(), ids=lambda p: p["id"])
@pytest.mark.parametrize("seed", SEEDS)
def test_prompt_is_honoured(prompt: dict[str, Any], seed: int, library: Path) -> None:
    expect: dict[str, str] = prompt["expect"]
    assert parse_attributes(prompt["prompt"], prompt["category"]) == expect
    made = synthesise(library, prompt["category"], None, seed, expect)
    assert made.attributes_honoured == expect, made.parts_how
    folder = library / made.folder
    meta = json.loads((folder / "asset.json").read_text())
    # an articulated asset's doors, drawers and their handles are its moving parts' visuals
    parts = (meta.get("articulation") or {}).get("parts", [])
    entries = meta["visual"] + [entry for part in parts for entry in part["visual"]]
    visuals = [Visual(folder, entry) for entry in entries]
    roles = sorted({k.partition(".")[0] for k in expect if "." in k})
    assert set(made.parts_how) == set(roles)
    assert not any(h.startswith("not honoured") for h in made.parts_how.values())
    size = meta["size"]
    for role in roles:
        mine = [v for v in visuals if f"__{role}_" in v.name]
        assert mine, f"no material of the {role} in {[v.name for v in visuals]}"
        for visual in mine:
            what = f"{prompt['id']} {role}"
            _check_look(visual, expect.get(f"{role}.colour"), expect.get(f"{role}.material"), what)
            # a part standing in for the one asked ("legs" on a pedestal table: its base)
            place = PLACES.get("base" if ": this" in made.parts_how[role] else role)
            if place is not None:
                assert place(visual.low, visual.high, size), (what, visual.low, visual.high)
    if "colour" in expect or "material" in expect:
        rest = [
            v
            for v in visuals
            if not any(f"__{r}_" in v.name for r in roles)
            and v.name.partition("__")[0] not in SECONDARY
        ]
        main = max(rest, key=lambda v: v.area)
        _check_look(main, expect.get("colour"), expect.get("material"), f"{prompt['id']} main")
    if "shape" in expect:
        _check_shape(expect["shape"], visuals, meta)
    for word in [v for k, v in expect.items() if k in ("colour", "shape")]:
        assert word in meta["description"]
