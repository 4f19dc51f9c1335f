"""The report page in memory: self-contained, with the plan, views, object table and validation."""

from __future__ import annotations

import base64
from typing import Any

from holomj.library import AssetLibrary
from holomj.mjcf.compiler import CompiledScene
from holomj.rendering import Rendering, RenderOptions, render_page, render_scene
from holomj.rendering.report_html import manifest_images
from holomj.spec.plan import ScenePlan
from holomj.spec.report import ObjectReport, StabilityReport
from tests.rendering.html_page import Page, parse_page


def _manifest(rendering: Rendering) -> dict[str, Any]:
    """A render manifest naming the images as the rendering does."""
    return {
        "plan": rendering.plan,
        "views": rendering.views,
        "options": rendering.options.to_dict(),
        "backend": rendering.backend,
        "gl_renderer": rendering.gl_renderer,
        "timings_s": rendering.timings_s,
    }


def _object_rows(page: Page) -> dict[str, list[str]]:
    return {row[0]: row for row in page.rows if row}


def _report(crate_stable: bool) -> StabilityReport:
    def obj(name: str, stable: bool, drift: float) -> ObjectReport:
        return ObjectReport(
            name=name,
            stable=stable,
            dynamic=True,
            displacement_m=drift,
            rotation_from_authored_deg=0.5,
            drift_m=drift,
            rotation_deg=0.5,
            path_m=drift,
            drop_m=0.0,
            fell=False,
            left_room=False,
            support="floor",
            expected_support="floor",
            penetration_m=0.0,
            at_rest=stable,
            reasons=[] if stable else ["drift 42.0 mm >= 10 mm"],
        )

    objects = [obj("crate", crate_stable, 0.042), obj("table", True, 0.0), obj("cube", True, 1e-4)]
    stable = sum(o.stable for o in objects)
    return StabilityReport(
        ok=crate_stable,
        source="two_room",
        objects=objects,
        counts={"objects": 3, "stable": stable, "penetrations": 0},
        warnings={} if crate_stable else {"mjWARN_BADQACC": 1},
        sim_time_s=8.0,
        wall_time_s=2.0,
        realtime_factor=4.0,
    )


def test_page_without_validation_says_not_validated(
    two_room_compiled: CompiledScene, two_room_library: AssetLibrary
) -> None:
    html = render_page(two_room_compiled.scene, two_room_library)
    page = parse_page(html)
    text = " ".join(page.text)
    assert "Not validated" in text and "holomj render OUT" in text  # no renders yet
    rows = _object_rows(page)
    assert set(rows) == {"crate", "table", "cube"}
    table = rows["table"]
    assert table[2] == "box" and table[3] == "builtin:box"
    assert table[4] == "1.20 × 0.80 × 0.75" and table[6] == "static"
    assert rows["cube"][7] == "table"  # its support
    assert all(row[8] == "not validated" for row in rows.values())
    assert page.external == [] and page.images == []


def test_page_shows_the_report_plan_notes_and_embedded_views(
    two_room_compiled: CompiledScene, two_room_library: AssetLibrary
) -> None:
    options = RenderOptions(("top", "rooms", "objects"), 64, 48, shadows=False)
    rendering = render_scene(two_room_compiled.model, two_room_compiled.scene, options)
    plan = ScenePlan(
        prompt="a kitchen & a living room <b>",
        planner="offline",
        seed=7,
        scene_type="apartment",
        rooms=[{"id": "kitchen", "type": "kitchen"}, {"id": "living", "type": "living_room"}],
        notes=["no sofa asset: used a box"],
    )
    manifest = _manifest(rendering)
    html = render_page(
        two_room_compiled.scene,
        two_room_library,
        report=_report(crate_stable=False),
        plan=plan,
        manifest=manifest,
        images=rendering.images,
    )
    page = parse_page(html)
    text = " ".join(page.text)
    assert "Not valid: 2/3 objects stable" in text
    assert "MuJoCo warning mjWARN_BADQACC: 1" in text
    assert "no sofa asset: used a box" in text
    assert "a kitchen & a living room <b>" in text  # escaped, shown as typed
    assert "rendered at 64×48" in text and "shadows off" in text
    rows = _object_rows(page)
    assert rows["crate"][8] == "no" and rows["crate"][9] == "42.00"
    assert "drift 42.0 mm" in rows["crate"][11]
    assert rows["table"][8] == "yes" and rows["cube"][9] == "0.10"
    # plan, two rooms and the table close-up, embedded as PNG data
    assert manifest_images(manifest) == [
        "plan.png",
        "rooms/kitchen.png",
        "rooms/living.png",
        "objects/table.png",
    ]
    assert len(page.images) == 4
    for src in page.images:
        assert src.startswith("data:image/png;base64,")
        assert base64.b64decode(src.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"


def test_images_given_as_urls_are_linked_and_missing_ones_left_out(
    two_room_compiled: CompiledScene, two_room_library: AssetLibrary
) -> None:
    manifest = {
        "plan": "renders/plan.png",
        "views": [
            {"kind": "top", "subject": None, "image": "renders/top.png"},
            {"kind": "room", "subject": "kitchen", "image": "renders/rooms/kitchen.png"},
            {"kind": "room", "subject": "living", "image": "renders/rooms/living.png"},
        ],
    }
    images = {"renders/plan.png": "renders/plan.png", "renders/rooms/kitchen.png": "a&b.png"}
    html = render_page(two_room_compiled.scene, two_room_library, manifest=manifest, images=images)
    assert parse_page(html).images == ["renders/plan.png", "a&b.png"]
    assert 'src="a&amp;b.png"' in html  # escaped in the markup
