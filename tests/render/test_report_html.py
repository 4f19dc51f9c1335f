"""report.html: a self-contained page with the plan, views, object table and validation."""

from __future__ import annotations

import base64
import json
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from holomj.errors import SpecError
from holomj.render import render_folder
from holomj.render.report_html import write_report_html
from holomj.spec.plan import ScenePlan
from holomj.spec.report import ObjectReport, StabilityReport


class _Page(HTMLParser):
    """Collects image sources, table rows (as cell texts) and the visible text."""

    def __init__(self) -> None:
        super().__init__()
        self.images: list[str] = []
        self.rows: list[list[str]] = []
        self.text: list[str] = []
        self._cell: list[str] | None = None
        self.external: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        if tag == "img":
            self.images.append(values.get("src") or "")
        if tag in ("link", "script"):
            self.external.append(tag)
        if tag == "tr":
            self.rows.append([])
        if tag == "td":
            self._cell = []

    def handle_endtag(self, tag: str) -> None:
        if tag == "td" and self._cell is not None:
            self.rows[-1].append("".join(self._cell).strip())
            self._cell = None

    def handle_data(self, data: str) -> None:
        self.text.append(data)
        if self._cell is not None:
            self._cell.append(data)


def _parse(path: Path) -> _Page:
    page = _Page()
    page.feed(path.read_text(encoding="utf-8"))
    return page


def _object_rows(page: _Page) -> dict[str, list[str]]:
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


def test_page_without_validation_says_not_validated(two_room_folder: Path) -> None:
    path = write_report_html(two_room_folder)
    assert path == two_room_folder / "report.html"
    page = _parse(path)
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


def test_page_shows_the_report_plan_notes_and_embedded_views(two_room_folder: Path) -> None:
    render_folder(two_room_folder, views="top,rooms,objects", width=64, height=48, shadows=False)
    report = _report(crate_stable=False)
    (two_room_folder / "report.json").write_text(report.model_dump_json())
    plan = ScenePlan(
        prompt="a kitchen & a living room <b>",
        planner="offline",
        seed=7,
        scene_type="apartment",
        rooms=[{"id": "kitchen", "type": "kitchen"}, {"id": "living", "type": "living_room"}],
        notes=["no sofa asset: used a box"],
    )
    (two_room_folder / "plan.json").write_text(plan.model_dump_json())
    page = _parse(write_report_html(two_room_folder))
    text = " ".join(page.text)
    assert "Not valid: 2/3 objects stable" in text
    assert "MuJoCo warning mjWARN_BADQACC: 1" in text
    assert "no sofa asset: used a box" in text
    assert "a kitchen & a living room <b>" in text  # escaped, shown as typed
    rows = _object_rows(page)
    assert rows["crate"][8] == "no" and rows["crate"][9] == "42.00"
    assert "drift 42.0 mm" in rows["crate"][11]
    assert rows["table"][8] == "yes" and rows["cube"][9] == "0.10"
    # plan, two rooms and the table close-up, embedded as PNG data
    assert len(page.images) == 4
    for src in page.images:
        assert src.startswith("data:image/png;base64,")
        assert base64.b64decode(src.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"


def test_linked_images_are_relative_and_exist(two_room_folder: Path) -> None:
    render_folder(two_room_folder, views="top,rooms", width=32, height=24, shadows=False)
    page = _parse(write_report_html(two_room_folder, embed=False))
    assert page.images and all(not Path(src).is_absolute() for src in page.images)
    for src in page.images:
        assert (two_room_folder / src).is_file()


def test_a_broken_report_json_is_bad_input(two_room_folder: Path) -> None:
    (two_room_folder / "report.json").write_text(json.dumps({"ok": "maybe"}))
    with pytest.raises(SpecError, match=r"report\.json") as info:
        write_report_html(two_room_folder)
    assert info.value.exit_code == 2
    assert not (two_room_folder / "report.html").exists()


def test_the_page_is_written_atomically(two_room_folder: Path) -> None:
    write_report_html(two_room_folder)
    leftovers = [p for p in two_room_folder.iterdir() if re.match(r"\.report\.html\.", p.name)]
    assert leftovers == []
