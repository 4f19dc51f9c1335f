"""Spawn-and-drop inside articulated furniture: onto a fridge's shelves and a drawer's bottom
with the doors and drawers closed, and generate's table of what goes inside what."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from shapely.geometry import Point

from holomj.compose.small_objects import (
    InsideRule,
    choose_small_objects,
    inside_rules,
    parse_inside_rules,
)
from holomj.errors import InputError, SpecError
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene, names
from holomj.physics.small_object_drops import drop_small_objects
from holomj.physics.spawn import populate
from holomj.physics.surfaces_world import world_interior_surfaces
from holomj.spec.plan import PlanObject, PlanSmallObject
from tests.layout.choosers import CategoryChooser
from tests.physics.spawn_helpers import receptacle_scene


def _owner_bodies(model: mujoco.MjModel, object_id: str) -> set[int]:
    """The carcass body of an object and its part bodies."""
    root = model.body(names.object_body(object_id)).id
    return {b for b in range(model.nbody) if b == root or model.body_parentid[b] == root}


def _settle(scene, library, ids: list[str], seconds: float = 2.0):
    model = compile_scene(scene, library).model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    bodies = {i: model.body(names.object_body(i)).id for i in ids}
    start = {i: data.xpos[b].copy() for i, b in bodies.items()}
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
    touching: dict[int, set[int]] = {}
    for k in range(data.ncon):
        b1, b2 = (int(b) for b in model.geom_bodyid[data.contact.geom[k]])
        touching.setdefault(b1, set()).add(b2)
        touching.setdefault(b2, set()).add(b1)
    return model, {
        i: (float(np.linalg.norm(data.xpos[b] - start[i])), touching.get(b, set()))
        for i, b in bodies.items()
    }


def test_things_go_onto_a_fridges_shelves(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("fridge_art_000")
    meta = default_library.get("fridge_art_000").meta
    result = populate(
        scene,
        default_library,
        "rec",
        [],
        np.random.default_rng(0),
        inside=[("apple", 2), ("bottle", 1)],
    )
    assert result.all_placed, result.to_dict()
    assert all(p.inside for p in result.placements)
    assert all(p.to_dict()["inside"] is True for p in result.placements)
    interior = world_interior_surfaces(scene.objects[0], meta)
    top = meta.size[2]
    for placement in result.placements:
        (surface,) = [s for s in interior if s.index == placement.surface_index]
        x, y, z = placement.final_pose["position"]  # type: ignore[index]
        assert surface.polygon.contains(Point(x, y)) and z < top - 0.05
    ids = [p.object_id for p in result.placements]
    model, settled = _settle(result.scene, default_library, ids)
    fridge = _owner_bodies(model, "rec")
    for object_id, (moved, touches) in settled.items():
        assert moved < 0.01 and touches & fridge, (object_id, moved)
    assert {o.support for o in result.scene.objects[1:]} == {"rec"}


def test_a_thing_goes_into_a_drawer_and_rests_on_the_drawer(
    default_library: AssetLibrary,
) -> None:
    scene = receptacle_scene("nightstand_art_000", yaw_deg=0.0)
    result = populate(
        scene, default_library, "rec", [], np.random.default_rng(1), inside=[("book", 1)]
    )
    (placement,) = result.placements
    assert placement.accepted, placement
    art = default_library.get("nightstand_art_000").meta.articulation
    assert art is not None
    surface = art.interior[placement.surface_index]  # type: ignore[index]
    assert surface.part is not None and surface.part.startswith("drawer_")
    model, settled = _settle(result.scene, default_library, [placement.object_id])
    moved, touches = settled[placement.object_id]
    drawer = model.body(names.object_part_body("rec", surface.part)).id
    assert moved < 0.01 and drawer in touches


def test_on_top_and_inside_in_one_call(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("dresser_art_000")
    result = populate(
        scene,
        default_library,
        "rec",
        [("candle", 1)],
        np.random.default_rng(2),
        inside=[("towel", 1)],
    )
    assert result.all_placed, result.to_dict()
    on_top, inside = result.placements
    assert not on_top.inside and "inside" not in on_top.to_dict() and inside.inside
    top = default_library.get("dresser_art_000").meta.size[2]
    assert on_top.final_pose["position"][2] >= top - 0.01  # type: ignore[index]
    assert inside.final_pose["position"][2] < top - 0.05  # type: ignore[index]
    assert len({on_top.object_id, inside.object_id}) == 2


def test_inside_needs_interior_surfaces(default_library: AssetLibrary) -> None:
    with pytest.raises(InputError, match="nothing to put things inside"):
        populate(
            receptacle_scene("dining_table_001"),
            default_library,
            "rec",
            [],
            np.random.default_rng(0),
            inside=[("apple", 1)],
        )


def test_the_inside_table_is_read_and_checked(default_library: AssetLibrary) -> None:
    rules = inside_rules()
    assert rules["fridge"].share == 1.0 and "apple" in dict(rules["fridge"].objects)
    for category, rule in rules.items():  # every category named is one the library has
        assert default_library.by_category(category), category
        for name, _ in rule.objects:
            assert any("object" in a.meta.placement for a in default_library.by_category(name))
    with pytest.raises(SpecError, match="fridge"):
        parse_inside_rules({"fridge": {"share": 2, "count": [1, 2], "objects": [["a", 1]]}}, "t")
    with pytest.raises(SpecError, match="malformed"):
        parse_inside_rules({"fridge": {"share": 1}}, "t")
    never = InsideRule(0.0, (1, 2), (("apple", 1.0),))
    assert never.draw(np.random.default_rng(0)) == []
    always = InsideRule(1.0, (2, 2), (("apple", 1.0), ("pear", 1.0)))
    drawn = always.draw(np.random.default_rng(0))
    assert len(drawn) == 2 and drawn == always.draw(np.random.default_rng(0))


def _choose_and_drop(scene, receptacles, library, chooser, seed, inside=False):
    """What generate does: the small objects chosen (compose), then dropped (physics)."""
    choices = choose_small_objects(scene, receptacles, library, chooser, seed, inside=inside)
    return drop_small_objects(scene, choices.drops, library), choices.picks


def test_generate_fills_a_fridge_the_plan_put_nothing_on(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("fridge_art_000")
    chooser = CategoryChooser(default_library)
    without, _ = _choose_and_drop(scene, [], default_library, chooser, seed=3)
    assert without.requested == 0 and without.scene == scene
    small, picks = _choose_and_drop(scene, [], default_library, chooser, seed=3, inside=True)
    (record,) = small.receptacles
    assert record["receptacle"] == "rec" and record["placed"] == []
    assert 2 <= small.requested <= 4 and small.inside == len(record["inside"]) >= 1
    assert picks and all(p["inside"] for p in picks)


def test_what_is_planned_on_a_lidded_box_goes_inside_it(default_library: AssetLibrary) -> None:
    # a toy box's lid moves: it has no top surface, so the toys planned on it go in it
    scene = receptacle_scene("toy_box_art_000")
    assert not default_library.get("toy_box_art_000").meta.surfaces
    toys = PlanSmallObject(name="toy ball", category="toy_ball", quantity=2)
    plan_obj = PlanObject(name="toy box", category="toy_box", on_top=[toys])
    chooser = CategoryChooser(default_library)
    small, _ = _choose_and_drop(scene, [("rec", plan_obj)], default_library, chooser, seed=1)
    (record,) = small.receptacles
    assert record["placed"] == [] and record["failures"] == []
    assert len(record["inside"]) == 2 and small.inside == 2
    # a receptacle with neither a top nor an inside reports them instead of failing
    bare = receptacle_scene("bean_bag_000")
    none, _ = _choose_and_drop(bare, [("rec", plan_obj)], default_library, chooser, seed=1)
    (record,) = none.receptacles
    assert none.requested == 2 and none.placed == 0
    assert all("no surface to put things on" in f["reason"] for f in record["failures"])
