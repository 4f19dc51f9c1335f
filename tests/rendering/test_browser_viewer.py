"""report.html's 3D view in a real headless Chromium (software WebGL), opened from file://: the
WebGL canvas draws the scene, a click on an object (simulated, and through the page's JS API)
shows its id and facts, and the layer toggles work (the quick start's apartment:
``tests/formats/test_report_page.py``).

Skips, visibly, when no chromium is installed (``bash scripts/setup.sh dev`` as root installs
it; CI does).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from holomj.jobs.render import write_report_html
from tests.rendering.browser import CHROMIUM, Browser

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (setup.sh dev)"),
]


def _page(folder: Path) -> Path:
    page = write_report_html(folder)
    assert page.stat().st_size < 20 * 2**20
    return page


def _canvas_box(browser: Browser) -> dict:
    return browser.evaluate(
        "(() => { const r = document.querySelector('#viewer-canvas canvas')"
        ".getBoundingClientRect(); return {x: r.left, y: r.top, w: r.width, h: r.height}; })()"
    )


def test_viewer_draws_and_clicks_show_the_object(two_room_folder: Path, tmp_path: Path) -> None:
    page = _page(two_room_folder)
    with Browser(tmp_path / "profile") as browser:
        browser.open(page.as_uri())
        state = browser.evaluate(
            "holomjViewer.ready.then(() => ({first: holomjViewer.firstFrameMs, "
            "ids: holomjViewer.objectIds(), stats: holomjViewer.pixelStats()}), "
            "e => ({error: String(e)}))"
        )
        assert "error" not in state, state
        assert sorted(state["ids"]) == ["crate", "cube", "table"]
        assert state["stats"]["lit"] > 0.05 and state["stats"]["std"] > 5, state["stats"]
        # the page's API selects an object and shows its facts
        info = browser.evaluate("holomjViewer.select('crate')")
        assert info["id"] == "crate" and info["category"] == "box" and info["room"] == "living"
        panel = browser.evaluate("document.getElementById('viewer-info').innerText")
        assert panel.startswith("crate") and "box" in panel
        # a simulated mouse click on the table selects it
        target = browser.evaluate("holomjViewer.screenPosition('table')")
        assert browser.evaluate(f"holomjViewer.pick({target['x']}, {target['y']})") == "table"
        box = _canvas_box(browser)
        browser.click(box["x"] + target["x"], box["y"] + target["y"])
        selected = "document.getElementById('viewer-info').getAttribute('data-selected')"
        assert browser.evaluate(selected) == "table"
        # hiding small objects deselects the cube; colliders show up on request
        browser.evaluate("holomjViewer.select('cube')")
        browser.evaluate("holomjViewer.setLayer('small', false)")
        assert browser.evaluate(selected) is None
        assert browser.evaluate("document.getElementById('layer-small').checked") is False
        before = browser.evaluate("holomjViewer.pixelStats()")["lit"]
        browser.evaluate("holomjViewer.setLayer('colliders', true)")
        assert browser.evaluate("holomjViewer.pixelStats()")["lit"] >= before
        shot = browser.screenshot(tmp_path / "viewer.png")
        assert browser.console_errors() == []
    pixels = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    canvas = pixels[
        int(box["y"]) + 5 : int(box["y"] + min(box["h"], pixels.shape[0] - box["y"])) - 5,
        int(box["x"]) + 5 : int(box["x"] + box["w"]) - 5,
    ]
    assert canvas.size and canvas.std() > 10, "the 3D view is blank in the screenshot"


def test_viewer_reports_no_webgl_and_keeps_the_images(
    two_room_folder: Path, tmp_path: Path
) -> None:
    page = _page(two_room_folder)
    profile = tmp_path / "profile"
    with Browser(profile, flags=["--disable-gpu", "--disable-software-rasterizer"]) as browser:
        browser.open(page.as_uri())
        error = browser.evaluate("holomjViewer.ready.then(() => null, e => String(e))")
        if error is None:
            pytest.skip("this chromium still has WebGL with --disable-gpu")
        status = browser.evaluate("document.getElementById('viewer-status').innerText")
        assert "3D view unavailable" in status
