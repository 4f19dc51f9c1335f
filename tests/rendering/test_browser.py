"""report.html in a real headless browser (Debian's chromium): it renders, and shows the table.

Skips, visibly, when no chromium is installed (``bash scripts/setup.sh dev`` as root installs
it; CI does).
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from holomj.library import AssetLibrary
from holomj.mjcf.compiler import CompiledScene
from holomj.rendering import RenderOptions, render_page, render_scene
from holomj.rendering.report_html import HEADER_COLOR

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--hide-scrollbars",
]

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (setup.sh dev)"),
]


def _chromium(tmp_path: Path, *args: str) -> subprocess.CompletedProcess[str]:
    profile = tmp_path / "chromium-profile"
    profile.mkdir(exist_ok=True)
    command = [str(CHROMIUM), *FLAGS, f"--user-data-dir={profile}", *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=120, check=False)


def test_report_page_renders_in_chromium_with_its_table(
    two_room_compiled: CompiledScene, two_room_library: AssetLibrary, tmp_path: Path
) -> None:
    options = RenderOptions(("top", "rooms"), 320, 240, shadows=False)
    rendering = render_scene(two_room_compiled.model, two_room_compiled.scene, options)
    manifest = {"plan": rendering.plan, "views": rendering.views}
    html = render_page(
        two_room_compiled.scene, two_room_library, manifest=manifest, images=rendering.images
    )
    page = tmp_path / "report.html"
    page.write_text(html, encoding="utf-8")
    url = page.resolve().as_uri()

    dom = _chromium(tmp_path, "--dump-dom", url)
    assert dom.returncode == 0, dom.stderr[-2000:]
    body_rows = re.findall(r"<tr[^>]*>\s*<td>([^<]+)</td>", dom.stdout)
    assert sorted(body_rows) == ["crate", "cube", "table"]
    assert dom.stdout.count("data:image/png;base64,") == 3  # plan and two rooms

    shot = tmp_path / "page.png"
    result = _chromium(tmp_path, f"--screenshot={shot}", "--window-size=1200,2600", url)
    assert result.returncode == 0 and shot.is_file(), result.stderr[-2000:]
    pixels = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    assert pixels.shape[:2] == (2600, 1200)
    assert pixels.std() > 20, "the screenshot is blank"
    header = np.array([int(HEADER_COLOR[i : i + 2], 16) for i in (1, 3, 5)])
    is_header = np.abs(pixels - header).max(axis=2) <= 6
    rows = np.flatnonzero(is_header.sum(axis=1) > 400)  # a wide band in the header's colour
    assert len(rows) >= 15, "the object table's header is not on screen"
    below = pixels[rows.max() + 2 : rows.max() + 80, 20:600]
    assert (below.max(axis=2) < 100).sum() > 200, "no table text below the header"
