"""Attribute-conditioned synthesis: colours, materials, shapes and styles asked of an asset."""

from __future__ import annotations

from dataclasses import replace

import pytest

from asset_pipeline.procedural import category_info, generate_asset
from asset_pipeline.procedural.attributes import (
    COLOURS,
    MATERIALS,
    Attributes,
    PartAttributes,
    attributes_from_text,
    colour_rgb,
)
from asset_pipeline.procedural.conditioning import parts_report
from tests.asset_pipeline.look_helpers import shows


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
    assert shows(upholstery, COLOURS["pink"], 1e-3)
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
    assert shows(_visual(chair, "black_leather")[0], COLOURS["black"])
    wardrobe = generate_asset("wardrobe", "w", None, 0, attributes_from_text("a white wardrobe"))
    assert "white" in wardrobe.meta.description
    # the carcass (largest surface) is white
    body = max(wardrobe.meta.visual, key=lambda v: len(wardrobe.files[v.mesh]))
    assert shows(body, COLOURS["white"])


def test_bed_frame_not_bedding_takes_the_colour() -> None:
    bed = generate_asset("bed", "b", None, 0, Attributes(colour="blue"))
    linen = [v for v in bed.meta.visual if v.mesh == "linen.obj"]
    assert linen and not shows(linen[0], COLOURS["blue"])
    assert any(shows(v, COLOURS["blue"]) for v in bed.meta.visual)


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
    assert any(shows(v, colour_rgb("burgundy")) for v in sofa.meta.visual)


def test_conditioned_synthesis_is_deterministic() -> None:
    asked = Attributes(colour="teal", material="linen", style="modern")
    a = generate_asset("armchair", "a", None, 3, asked)
    b = generate_asset("armchair", "a", None, 3, asked)
    assert a.meta == b.meta and a.files == b.files
    # no attributes: exactly the category generator's asset
    assert generate_asset("armchair", "a", None, 3, Attributes()) == generate_asset(
        "armchair", "a", None, 3
    )


# --- part attributes -----------------------------------------------------------------------
@pytest.mark.parametrize(
    ("text", "category", "expected"),
    [
        ("white kitchen cabinets with brass handles", "kitchen_cabinet",
         {"colour": "white", "handles.material": "brass"}),
        ("a wooden table with metal legs", "dining_table",
         {"material": "wood", "legs.material": "metal"}),
        ("a sofa with wooden legs", "sofa", {"legs.material": "wood"}),
        ("a chair with a red seat", "dining_chair", {"seat.colour": "red"}),
        ("a lamp with a white shade", "floor_lamp", {"shade.colour": "white"}),
        ("a desk with black drawers", "desk", {"drawers.colour": "black"}),
        ("a coffee table with a glass top and black metal legs", "coffee_table",
         {"top.material": "glass", "legs.colour": "black", "legs.material": "metal"}),
        ("a glass-topped coffee table", None, {"top.material": "glass"}),
        ("a glass top coffee table", "coffee_table", {"top.material": "glass"}),
        # inside a hyphenated word only its own words are the part's
        ("a black metal-legged table", None, {"colour": "black", "legs.material": "metal"}),
        ("a table with legs in black metal, and a marble top", None,
         {"top.material": "marble", "legs.colour": "black", "legs.material": "metal"}),
        ("an off-white sofa with blue velvet cushions", "sofa",
         {"colour": "off-white", "cushions.colour": "blue", "cushions.material": "velvet"}),
        # a part noun followed by another noun is not a part ("base cabinet", "top shelf")
        ("a white base cabinet", None, {"colour": "white"}),
        ("a lamp on top of the desk", None, {}),
        ("a desk with drawers", "desk", {}),
        # a category's own words are never a part: a picture frame is not asked a frame colour
        ("a black picture frame", "picture_frame", {"colour": "black"}),
    ],
)  # fmt: skip
def test_part_attributes_from_text(text: str, category: str | None, expected: dict) -> None:
    assert attributes_from_text(text, category).to_dict() == expected


def test_attributes_round_trip_with_parts() -> None:
    asked = attributes_from_text("a round white table with a glass top and oak legs")
    assert Attributes.from_dict(asked.to_dict()) == asked
    assert asked.hard == {k: v for k, v in asked.to_dict().items() if k != "style"}
    assert "legs.material=oak" in asked.key()
    assert Attributes.from_dict({"wings.colour": "red", "colour": "red"}).to_dict() == {
        "colour": "red"
    }  # unknown parts are ignored, as unknown keys are
    with pytest.raises(ValueError):
        PartAttributes("legs")  # neither colour nor material


def _by_name(bundle, needle: str):
    return [v for v in bundle.meta.visual if needle in v.mesh]


def test_part_request_recolours_only_those_parts() -> None:
    asked = attributes_from_text("white kitchen cabinets with brass handles", "kitchen_cabinet")
    for seed in range(3):
        cabinet = generate_asset("kitchen_cabinet", "k", None, seed, asked)
        (handles,) = _by_name(cabinet, "__handles_")
        assert shows(handles, MATERIALS["brass"].rgba[:3])
        others = [v for v in cabinet.meta.visual if v is not handles]
        assert all(shows(v, COLOURS["white"]) for v in others)
        assert cabinet.meta.attributes == {"colour": "white", "handles.material": "brass"}
        assert "brass handles" in cabinet.meta.description


def test_design_is_redrawn_until_it_has_the_part() -> None:
    asked = attributes_from_text("a sofa with wooden legs", "sofa")
    for seed in range(6):
        report = parts_report(category_info("sofa"), None, seed, asked)
        assert report["legs"].startswith("wooden on the legs (4 parts)")


def test_a_missing_part_is_reported_not_faked() -> None:
    asked = attributes_from_text("a sofa with brass handles", "sofa")
    sofa = generate_asset("sofa", "s", None, 0, asked)
    assert sofa.meta.attributes == {}
    assert not _by_name(sofa, "__handles_")
    assert parts_report(category_info("sofa"), None, 0, asked) == {
        "handles": "not honoured: this sofa has no handles"
    }


def test_a_stand_in_part_is_said() -> None:
    asked = attributes_from_text("a round coffee table with black legs", "coffee_table")
    table = generate_asset("coffee_table", "t", (0.8, 0.8, 0.42), 0, asked)
    assert table.meta.attributes == {"shape": "round", "legs.colour": "black"}
    report = parts_report(category_info("coffee_table"), (0.8, 0.8, 0.42), 0, asked)
    assert report["legs"].startswith("black on the base") and "has no legs" in report["legs"]
    assert "black" in table.meta.description


def test_object_colour_goes_to_the_parts_no_request_names() -> None:
    asked = attributes_from_text("a wooden table with a glass top", "dining_table")
    for seed in range(4):
        table = generate_asset("dining_table", "t", None, seed, asked)
        (top,) = _by_name(table, "__top_")
        assert top.rgba[3] < 1.0  # glass
        rest = [v for v in table.meta.visual if v is not top]
        assert any(shows(v, MATERIALS["wood"].rgba[:3]) for v in rest)


def test_role_tags_do_not_change_the_assets() -> None:
    from asset_pipeline.procedural.assembly import assemble
    from asset_pipeline.procedural.catalog import design_for
    from asset_pipeline.procedural.roles import role_of, untagged

    for category in ("sofa", "dining_chair", "desk", "kitchen_cabinet", "floor_lamp", "bed"):
        design, size = design_for(category, "a", None, 1)
        assert any(role_of(p) for p in design.parts)
        plain = replace(design, parts=tuple(untagged(p) for p in design.parts))
        tagged_bundle, plain_bundle = assemble(design, size), assemble(plain, size)
        assert tagged_bundle.files == plain_bundle.files
        assert tagged_bundle.meta == plain_bundle.meta


def test_l_shaped_desk() -> None:
    desk = generate_asset("desk", "d", (0.7, 1.4, 0.75), 0, Attributes(shape="l-shaped"))
    assert desk.meta.attributes == {"shape": "l-shaped"}
    assert desk.meta.size == (0.9, 1.4, 0.75)  # as deep as a desk may be: the return shows
    tops = [s for s in desk.meta.surfaces if s.height > 0.7]
    assert len(tops) == 2 and 0.4 < sum(s.area_m2 for s in tops) / (0.9 * 1.4) < 0.9
    assert "l-shaped" in desk.meta.description
