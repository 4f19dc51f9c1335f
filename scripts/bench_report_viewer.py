"""Measure report.html's 3D view: page size, GLB size, and time to the first frame in headless
Chromium with its software WebGL (SwiftShader), the way the tests open it (from file://).

    .venv/bin/python scripts/bench_report_viewer.py out/example [more folders] [--runs 3]

Writes each folder's report.html afresh (with the 3D view), opens it ``--runs`` times and prints
one JSON line per folder: page bytes, GLB bytes, the page's own timings (ms from navigation
start: viewer script, GLB decoded, GLB parsed, first frame drawn and read back) and the time of
one more frame. Needs Debian's chromium (``bash scripts/setup.sh dev`` as root installs it).
"""

from __future__ import annotations

import argparse
import base64
import json
import re
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from holomj.jobs.render import write_report_html  # noqa: E402
from tests.rendering.browser import CHROMIUM, Browser  # noqa: E402


def measure(folder: Path, runs: int) -> dict:
    start = time.perf_counter()
    page = write_report_html(folder)
    build_s = time.perf_counter() - start
    html = page.read_text(encoding="utf-8")
    glb = re.search(r'id="viewer-glb">([^<]*)</script>', html)
    samples = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory() as profile, Browser(Path(profile)) as browser:
            browser.open(page.as_uri())
            state = browser.evaluate(
                "holomjViewer.ready.then(() => ({first: holomjViewer.firstFrameMs, "
                "timings: holomjViewer.timings, objects: holomjViewer.objectIds().length}))"
            )
            state["frame_ms"] = round(browser.evaluate("holomjViewer.timeFrame()"))
            samples.append(state)
    firsts = [s["first"] for s in samples]
    return {
        "folder": str(folder),
        "page_bytes": page.stat().st_size,
        "glb_bytes": len(base64.b64decode(glb.group(1))) if glb else 0,
        "report_build_s": round(build_s, 2),
        "objects": samples[0]["objects"],
        "first_frame_ms": firsts,
        "first_frame_median_ms": statistics.median(firsts),
        "timings_ms": [s["timings"] for s in samples],
        "next_frame_ms": [s["frame_ms"] for s in samples],
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", type=Path)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    if CHROMIUM is None:
        print("chromium is not installed (bash scripts/setup.sh dev, as root)", file=sys.stderr)
        return 1
    for folder in args.folders:
        print(json.dumps(measure(folder, args.runs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
