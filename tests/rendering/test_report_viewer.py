"""The report page's 3D view, as text: the GLB and the object facts embedded, three.js and the
viewer inlined (nothing to fetch), safe against markup in the data, hidden when printed."""

from __future__ import annotations

import base64
import json
import re

from holomj.formats.glb import scene_glb
from holomj.library import AssetLibrary
from holomj.mjcf.compiler import CompiledScene
from holomj.rendering import render_page
from holomj.rendering.report_html import THREE_JS, THREE_LICENSE, VIEWER_JS
from holomj.spec.report import StabilityReport
from tests.rendering.test_report_html import _report


def _block(html: str, ident: str) -> str:
    match = re.search(rf'<script type="[^"]+" id="{ident}">(.*?)</script>', html, re.S)
    assert match, ident
    return match.group(1)


def test_page_embeds_the_glb_facts_and_scripts(
    two_room_compiled: CompiledScene, two_room_library: AssetLibrary
) -> None:
    glb = scene_glb(two_room_compiled.model, two_room_compiled.scene, colliders=True)
    report: StabilityReport = _report(crate_stable=False)
    html = render_page(two_room_compiled.scene, two_room_library, report=report, glb=glb)
    assert '<section id="view3d">' in html and 'id="viewer-canvas"' in html
    assert base64.b64decode(_block(html, "viewer-glb")) == glb
    facts = json.loads(_block(html, "viewer-objects"))
    assert set(facts) == {"crate", "table", "cube"}
    assert facts["crate"]["verdict"] == "not stable" and facts["crate"]["stable"] is False
    assert facts["table"]["category"] == "box" and facts["table"]["static"] is False  # as validated
    assert facts["cube"]["support"] == "table" and facts["cube"]["mass_kg"] > 0
    for box in ("colliders", "ceilings", "small"):
        assert f'id="layer-{box}"' in html
    # everything inline: no script or style is fetched, so file:// works offline
    assert not re.search(r"<script[^>]*\bsrc=", html) and "<link" not in html
    assert "var HOLOMJ_THREE=" in html and "window.holomjViewer = api" in html
    assert "@media print { #view3d { display: none; } }" in html
    # three.js ships with its licence
    assert "MIT License" in THREE_LICENSE.read_text() and THREE_JS.stat().st_size > 100_000
    assert "</script" not in VIEWER_JS.read_text() and "</script" not in THREE_JS.read_text()


def test_markup_in_the_facts_cannot_close_the_script(
    two_room_compiled: CompiledScene, two_room_library: AssetLibrary
) -> None:
    report = _report(crate_stable=False)
    crate = next(o for o in report.objects if o.name == "crate")
    odd = crate.model_copy(update={"reasons": ["fell </script><script>alert(1)</script>"]})
    report = report.model_copy(
        update={"objects": [odd if o.name == "crate" else o for o in report.objects]}
    )
    glb = scene_glb(two_room_compiled.model, two_room_compiled.scene)
    html = render_page(two_room_compiled.scene, two_room_library, report=report, glb=glb)
    facts = json.loads(_block(html, "viewer-objects"))
    assert facts["crate"]["reasons"] == ["fell </script><script>alert(1)</script>"]
    assert html.count("<script") == 4  # data, GLB, three.js, viewer


def test_page_without_a_glb_has_no_scripts(
    two_room_compiled: CompiledScene, two_room_library: AssetLibrary
) -> None:
    html = render_page(two_room_compiled.scene, two_room_library)
    assert "<script" not in html and 'id="view3d"' not in html
