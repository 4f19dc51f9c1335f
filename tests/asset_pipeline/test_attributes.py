"""Attribute-conditioned synthesis: colours, materials, shapes and styles asked of an asset."""

from __future__ import annotations

import pytest

from asset_pipeline.procedural import generate_asset
from asset_pipeline.procedural.attributes import (
    COLOURS,
    MATERIALS,
    Attributes,
    attributes_from_text,
    colour_rgb,
)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("a pink velvet sofa", {"colour": "pink", "material": "velvet"}),
        ("a black leather armchair", {"colour": "black", "material": "leather"}),
        ("a white wardrobe", {"colour": "white"}),
        ("a round glass coffee table", {"material": "glass", "shape": "round"}),
        ("a light blue oval dining table", {"colour": "light blue", "shape": "oval"}),
        ("a dark green round mirror", {"colour": "dark green", "shape": "round"}),
        ("a rustic oak bed", {"material": "oak", "style": "rustic"}),
        ("a mid-century armchair", {"style": "mid-century"}),
        ("a Gray stainless steel fridge", {"colour": "grey", "material": "steel"}),
        ("a cast iron kettlebell", {"material": "iron"}),
        # only the head counts: the cloth is white, not the table
        ("a banquet table with a white cloth", {}),
        ("an upholstered sofa", {}),
    ],
)
def test_attributes_from_text(text: str, expected: dict[str, str]) -> None:
    assert attributes_from_text(text).to_dict() == expected


def test_category_words_are_not_attributes() -> None:
    assert attributes_from_text("an orange", "orange").to_dict() == {}
    assert attributes_from_text("an orange", None).to_dict() == {"colour": "orange"}


def test_word_lists_are_large_enough() -> None:
    assert len(COLOURS) >= 30
    for name in ("oak", "walnut", "pine", "cherry", "maple", "painted wood", "metal", "chrome",
                 "brass", "steel", "leather", "fabric", "velvet", "linen", "marble", "glass",
                 "plastic", "ceramic", "wicker"):  # fmt: skip
        assert name in MATERIALS
    light, dark, base = colour_rgb("light blue"), colour_rgb("dark blue"), colour_rgb("blue")
    assert all(lo < b < hi for lo, b, hi in zip(dark, base, light, strict=True))
    with pytest.raises(ValueError):
        Attributes(colour="plaid")


def _visual(bundle, needle: str):
    return [v for v in bundle.meta.visual if needle in v.mesh]


def test_pink_velvet_sofa_has_pink_upholstery() -> None:
    plain = generate_asset("sofa", "sofa_x", (0.9, 2.0, 0.85), 0)
    asked = Attributes(colour="pink", material="velvet")
    pink = generate_asset("sofa", "sofa_x", (0.9, 2.0, 0.85), 0, asked)
    assert pink.meta.attributes == {"colour": "pink", "material": "velvet"}
    assert "pink velvet" in pink.meta.description and "sofa" in pink.meta.description
    (upholstery,) = _visual(pink, "pink_velvet")
    assert upholstery.rgba[:3] == pytest.approx(COLOURS["pink"], abs=1e-3)
    assert upholstery.specular == MATERIALS["velvet"].specular
    # the upholstery is the sofa's largest surface: its file is the biggest mesh
    assert len(pink.files[upholstery.mesh]) == max(
        len(pink.files[v.mesh]) for v in pink.meta.visual
    )
    # same geometry as the plain sofa of that seed, other colour
    assert len(pink.meta.visual) == len(plain.meta.visual)
    assert pink.meta.size == plain.meta.size
    assert pink.meta.collision == plain.meta.collision


def test_black_leather_armchair_and_white_wardrobe() -> None:
    chair = generate_asset(
        "armchair", "a", None, 1, attributes_from_text("a black leather armchair")
    )
    assert "black leather" in chair.meta.description
    assert _visual(chair, "black_leather")[0].rgba[:3] == pytest.approx(COLOURS["black"])
    wardrobe = generate_asset("wardrobe", "w", None, 0, attributes_from_text("a white wardrobe"))
    assert "white" in wardrobe.meta.description
    # the carcass (largest surface) is white
    body = max(wardrobe.meta.visual, key=lambda v: len(wardrobe.files[v.mesh]))
    assert body.rgba[:3] == pytest.approx(COLOURS["white"])


def test_bed_frame_not_bedding_takes_the_colour() -> None:
    bed = generate_asset("bed", "b", None, 0, Attributes(colour="blue"))
    linen = [v for v in bed.meta.visual if v.mesh == "linen.obj"]
    assert linen and linen[0].rgba[:3] != pytest.approx(COLOURS["blue"])
    assert any(v.rgba[:3] == pytest.approx(COLOURS["blue"]) for v in bed.meta.visual)


@pytest.mark.parametrize("category", ["coffee_table", "side_table", "dining_table"])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_round_tables_have_a_round_top(category: str, seed: int) -> None:
    size = {"coffee_table": (0.6, 1.1, 0.42), "side_table": (0.45, 0.5, 0.55)}.get(
        category, (0.9, 1.6, 0.75)
    )
    table = generate_asset(category, "t", size, seed, Attributes(shape="round"))
    x, y, _ = table.meta.size
    assert x == pytest.approx(y) == pytest.approx(min(size[:2]))
    top = max(table.meta.surfaces, key=lambda s: s.height)
    assert len(top.polygon) >= 16  # a circle, not a rectangle
    assert table.meta.attributes == {"shape": "round"}
    assert "round" in table.meta.description


def test_square_and_oval_tables() -> None:
    square = generate_asset("dining_table", "t", (1.0, 1.6, 0.75), 0, Attributes(shape="square"))
    assert square.meta.size[0] == square.meta.size[1] == 1.0
    assert len(max(square.meta.surfaces, key=lambda s: s.height).polygon) == 4
    oval = generate_asset(
        "dining_table", "t", (0.9, 1.6, 0.75), 0, attributes_from_text("an oval walnut table")
    )
    assert oval.meta.size == (0.9, 1.6, 0.75)
    top = max(oval.meta.surfaces, key=lambda s: s.height)
    assert len(top.polygon) >= 16
    xs = [p[0] for p in top.polygon]
    ys = [p[1] for p in top.polygon]
    assert max(ys) - min(ys) > 1.5 * (max(xs) - min(xs))  # an ellipse, long along Y
    assert oval.meta.attributes == {"material": "walnut", "shape": "oval"}
    assert "oval walnut" in oval.meta.description


def test_round_mirror() -> None:
    mirror = generate_asset("mirror", "m", (0.03, 0.6, 0.9), 0, Attributes(shape="round"))
    assert mirror.meta.size == (0.03, 0.6, 0.6)
    assert mirror.meta.placement == ["wall"]
    assert "round" in mirror.meta.description
    # a shape the category cannot take is not claimed
    sofa = generate_asset("sofa", "s", None, 0, Attributes(shape="round", colour="red"))
    assert sofa.meta.attributes == {"colour": "red"}


def test_style_biases_the_main_material() -> None:
    sofa = generate_asset("sofa", "s", None, 0, Attributes(style="victorian"))
    assert sofa.meta.attributes == {"style": "victorian"}
    assert "velvet" in sofa.meta.description and "victorian" in sofa.meta.description
    assert any(v.rgba[:3] == pytest.approx(colour_rgb("burgundy")) for v in sofa.meta.visual)


def test_conditioned_synthesis_is_deterministic() -> None:
    asked = Attributes(colour="teal", material="linen", style="modern")
    a = generate_asset("armchair", "a", None, 3, asked)
    b = generate_asset("armchair", "a", None, 3, asked)
    assert a.meta == b.meta and a.files == b.files
    # no attributes: exactly the category generator's asset
    assert generate_asset("armchair", "a", None, 3, Attributes()) == generate_asset(
        "armchair", "a", None, 3
    )
