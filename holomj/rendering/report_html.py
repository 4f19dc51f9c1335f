"""The report page: one self-contained HTML page about a scene, readable from ``file://``.

Images are embedded as base64 ``data:`` URIs, so the page stands alone: it can be copied, mailed
or kept as a CI artifact without the images beside it (or linked relatively instead, for a
lighter page). No external scripts, styles or fonts: nothing is fetched when the page is viewed.

Given the scene's GLB (:mod:`holomj.formats.glb`), the page opens with an interactive 3D view: the
GLB embedded as base64, drawn by three.js (``vendor/three-viewer.min.js``: three.js's core,
GLTFLoader and OrbitControls bundled into one classic script, MIT licence in
``vendor/three.LICENSE.txt``, rebuilt by ``scripts/build_viewer_vendor.sh``) and ``viewer.js``,
all inlined, so it works from ``file://`` offline. Orbit, pan and zoom; click an object to see
its id, category, asset, mass and stability verdict; toggles for colliders, ceilings and small
objects. ``window.holomjViewer`` is its JS API (see ``viewer.js``). The 3D view is left out of
printed pages; the PNG views stay for quick looks and for print.

Sections: verdict, 3D view, plan, room views, close-ups, the object table (category, asset, size,
mass, stable, moved and turned from the authored pose from the validation report when there is
one, "not validated" otherwise), the validation details, the planner's notes, import notes and
render facts. :func:`render_page` builds the text from data in memory; the render job
(:mod:`holomj.jobs.render`) reads a folder's reports and renders and writes ``report.html``.
"""

from __future__ import annotations

import base64
import json
from collections.abc import Mapping
from functools import cache
from html import escape
from pathlib import Path
from typing import Any

from holomj.library.store import AssetLibrary
from holomj.rendering.report_objects import object_facts, object_table
from holomj.spec.plan import ScenePlan
from holomj.spec.report import StabilityReport
from holomj.spec.scene import SceneSpec
from holomj.version import __version__

HEADER_COLOR = "#2c3e50"  # the table header; the browser test looks for it
VIEWER_JS = Path(__file__).with_name("viewer.js")
THREE_JS = Path(__file__).parent / "vendor" / "three-viewer.min.js"
THREE_LICENSE = Path(__file__).parent / "vendor" / "three.LICENSE.txt"

_CSS = f"""
body {{ font-family: system-ui, -apple-system, "Segoe UI", sans-serif; margin: 24px;
       color: #222; background: #fafafa; }}
h1 {{ margin-bottom: 4px; }} h2 {{ margin-top: 28px; border-bottom: 1px solid #ccc; }}
.sub {{ color: #555; margin-top: 0; }}
.verdict {{ padding: 10px 14px; border-radius: 6px; font-weight: 600; display: inline-block; }}
.ok {{ background: #d7f5dd; color: #145a22; }} .bad {{ background: #fbdcdc; color: #8a1111; }}
.none {{ background: #eee; color: #444; }}
.grid {{ display: flex; flex-wrap: wrap; gap: 14px; }}
figure {{ margin: 0; background: white; padding: 6px; border: 1px solid #ddd;
          display: inline-block; }}
figure img {{ display: block; max-width: 100%; height: auto; }}
figure.room img {{ width: 560px; }}
figcaption {{ font-size: 13px; color: #444; padding-top: 4px; }}
table {{ border-collapse: collapse; font-size: 13px; background: white; }}
th {{ background: {HEADER_COLOR}; color: white; text-align: left; padding: 6px 8px; }}
td {{ border-top: 1px solid #ddd; padding: 4px 8px; vertical-align: top; }}
td.num {{ text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }}
tr.unstable td {{ background: #fdeaea; }}
ul {{ margin-top: 4px; }} code {{ background: #eee; padding: 0 3px; }}
.viewer-wrap {{ display: flex; gap: 14px; align-items: flex-start; flex-wrap: wrap; }}
#viewer-canvas {{ flex: 1 1 640px; min-width: 320px; height: 620px; border: 1px solid #ccc;
                  background: #e9edf1; position: relative; }}
#viewer-canvas canvas {{ display: block; width: 100%; height: 100%; }}
.viewer-side {{ flex: 0 0 300px; font-size: 13px; }}
.viewer-side label {{ display: block; margin: 2px 0; }}
.viewer-side button {{ margin-top: 6px; }}
#viewer-info {{ margin-top: 12px; background: white; border: 1px solid #ddd; padding: 8px;
                min-height: 60px; }}
#viewer-info .viewer-title {{ font-weight: 600; font-size: 14px; margin-bottom: 4px;
                              word-break: break-all; }}
#viewer-info th {{ background: none; color: #555; padding: 2px 6px 2px 0; }}
#viewer-info td {{ border: none; padding: 2px 0; }}
#viewer-status {{ color: #555; font-size: 12px; }}
@media print {{ #view3d {{ display: none; }} }}
"""


def render_page(
    scene: SceneSpec,
    library: AssetLibrary,
    *,
    report: StabilityReport | None = None,
    plan: ScenePlan | None = None,
    imported: Any = None,
    manifest: Mapping[str, Any] | None = None,
    images: Mapping[str, bytes | str] | None = None,
    glb: bytes | None = None,
) -> str:
    """The HTML text of the page for ``scene``.

    ``library`` gives the assets' category, size and mass; ``report``: the validation report,
    ``plan``: the planner's plan, ``imported``: the import report (JSON data), ``manifest``: the
    render summary (JSON form; None: not rendered yet). ``images`` maps the image paths the
    manifest names to their PNG bytes (embedded as ``data:`` URIs) or to a URL to link them by;
    images it lacks are left out. ``glb``: the scene as GLB (with its colliders) for the 3D
    view; None leaves the view out (and the page without scripts).
    """
    images = images or {}
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{escape(scene.name)} — holomj report</title>",
        f"<style>{_CSS}</style></head><body>",
        f"<h1>{escape(scene.name)}</h1>",
        f'<p class="sub">{_counts(scene)}</p>',
        _verdict(report),
        _viewer(scene, library, report, glb) if glb is not None else "",
        _images(manifest, images),
        object_table(scene, library, report),
        _validation(report),
        _plan_notes(plan),
        _import_notes(imported),
        _render_facts(manifest),
        f'<p class="sub">holomj {escape(__version__)}</p>',
        "</body></html>",
    ]
    return "\n".join(p for p in parts if p) + "\n"


def manifest_images(manifest: Mapping[str, Any] | None) -> list[str]:
    """The paths of the images the page shows from a render ``manifest``: plan, then views."""
    if manifest is None:
        return []
    paths = [manifest["plan"]] if manifest.get("plan") else []
    paths += [
        v["image"]
        for v in manifest.get("views", [])
        if v.get("kind") in ("room", "object") and v.get("image")
    ]
    return paths


def _counts(scene: SceneSpec) -> str:
    text = (
        f"{len(scene.rooms)} rooms, {len(scene.objects)} objects, {len(scene.doors)} doors, "
        f"{len(scene.windows)} windows"
    )
    if scene.source:
        text += f" · source: {scene.source}"
    return escape(text)


def _verdict(report: StabilityReport | None) -> str:
    if report is None:
        return (
            '<p class="verdict none">Not validated: run <code>holomj validate OUT --json '
            "OUT/report.json</code></p>"
        )
    c = report.counts
    text = (
        f"{c.get('stable', 0)}/{c.get('objects', len(report.objects))} objects stable, "
        f"{len(report.penetrations)} penetrations at t = 0, "
        f"{sum(report.warnings.values())} MuJoCo warnings"
    )
    label, css = ("Physically valid", "ok") if report.ok else ("Not valid", "bad")
    return f'<p class="verdict {css}">{label}: {escape(text)}</p>'


def _image_src(images: Mapping[str, bytes | str], path: str) -> str | None:
    image = images.get(path)
    if image is None:
        return None
    if isinstance(image, bytes):
        return "data:image/png;base64," + base64.b64encode(image).decode("ascii")
    return escape(image)


def _figure(src: str | None, caption: str, css: str) -> str:
    if src is None:
        return ""
    return (
        f'<figure class="{css}"><img src="{src}" alt="{escape(caption)}">'
        f"<figcaption>{escape(caption)}</figcaption></figure>"
    )


def _images(manifest: Mapping[str, Any] | None, images: Mapping[str, bytes | str]) -> str:
    if manifest is None:
        return (
            "<h2>Views</h2><p>No renders yet: run <code>holomj render OUT</code> to add the "
            "plan and the room views.</p>"
        )
    parts = []
    plan = manifest.get("plan")
    if plan:
        parts += ["<h2>Plan</h2>", _figure(_image_src(images, plan), "plan", "plan")]
    groups = [("room", "Rooms"), ("object", "Close-ups of receptacles")]
    for kind, title in groups:
        figures = [
            _figure(_image_src(images, v["image"]), str(v.get("subject")), "room")
            for v in manifest.get("views", [])
            if v.get("kind") == kind
        ]
        if any(figures):
            parts += [f"<h2>{title}</h2>", '<div class="grid">', *figures, "</div>"]
    return "\n".join(parts)


def _viewer(
    scene: SceneSpec, library: AssetLibrary, report: StabilityReport | None, glb: bytes
) -> str:
    """The 3D view: controls, info panel, the GLB and object facts as data, and the scripts."""
    by_name = {o.name: o for o in report.objects} if report is not None else {}
    facts = {}
    for obj in scene.objects:
        entry = object_facts(obj, library, by_name.get(obj.id), report is not None)
        entry.pop("size")
        if entry["mass_kg"] is not None:
            entry["mass_kg"] = round(float(entry["mass_kg"]), 3)
        for key in ("moved_mm", "turned_deg"):
            if key in entry:
                entry[key] = round(float(entry[key]), 2)
        facts[obj.id] = entry
    toggles = "".join(
        f'<label><input type="checkbox" id="layer-{name}"{" checked" if on else ""}> '
        f"{escape(label)}</label>"
        for name, label, on in (
            ("colliders", "colliders", False),
            ("ceilings", "ceilings", False),
            ("small", "small objects", True),
        )
    )
    data = base64.b64encode(glb).decode("ascii")
    return "\n".join(
        [
            '<section id="view3d"><h2>3D view</h2><div class="viewer-wrap">',
            '<div id="viewer-canvas"></div>',
            f'<div class="viewer-side">{toggles}'
            '<button type="button" id="viewer-reset">reset view</button>'
            '<div id="viewer-info">Click an object to see what it is.</div>'
            '<p id="viewer-status">The 3D view needs JavaScript and WebGL.</p></div></div>',
            f'<script type="application/json" id="viewer-objects">{_script_json(facts)}</script>',
            f'<script type="application/octet-stream" id="viewer-glb">{data}</script>',
            f"<script>{_script_text(THREE_JS)}</script>",
            f"<script>{_script_text(VIEWER_JS)}</script>",
            "</section>",
        ]
    )


def _script_json(data: Any) -> str:
    """JSON safe inside a ``<script>`` element: no ``<`` at all (``\\u003c`` in strings)."""
    text = json.dumps(data, sort_keys=True, ensure_ascii=True, separators=(",", ":"))
    return text.replace("<", "\\u003c").replace(">", "\\u003e")


@cache
def _script_text(path: Path) -> str:
    """A shipped script, safe to inline (it must not close its ``<script>`` element)."""
    text = path.read_text(encoding="utf-8")
    return text.replace("</script", "<\\/script")


def _validation(report: StabilityReport | None) -> str:
    if report is None:
        return ""
    items = [
        f"furniture validated as: {report.furniture}",
        f"settled: {'yes' if report.settled else 'no'} after {report.settle_time_s:.2f} s; "
        f"monitored {report.monitor_s:.2f} s",
        f"max penetration at t = 0: {report.max_penetration_m * 1000:.2f} mm; deepest contact "
        f"while monitoring: {report.max_contact_depth_m * 1000:.2f} mm",
        "held static (not put to the test): " + (", ".join(report.static_objects) or "none"),
        f"{report.sim_time_s:.1f} s simulated in {report.wall_time_s:.1f} s "
        f"({report.realtime_factor:.1f}× real time)",
    ]
    items += [
        f"penetration {p.a} / {p.b}: {p.depth_m * 1000:.1f} mm ({p.geom_a} / {p.geom_b})"
        for p in report.penetrations
    ]
    items += [f"below the floor: {d.name} (lowest z {d.value_m:.3f} m)" for d in report.below_floor]
    items += [f"outside the rooms: {d.name} ({d.value_m:.3f} m away)" for d in report.outside_rooms]
    items += [f"MuJoCo warning {name}: {count}" for name, count in sorted(report.warnings.items())]
    items += [
        f"repaired {a.name}: moved {a.moved_m * 1000:.1f} mm ({a.why})" for a in report.repaired
    ]
    items += [f"could not repair {u.name}: {u.why}" for u in report.unsaved]
    lis = "".join(f"<li>{escape(i)}</li>" for i in items)
    return f"<h2>Validation</h2><ul>{lis}</ul>"


def _plan_notes(plan: ScenePlan | None) -> str:
    if plan is None:
        return ""
    facts = [
        f"prompt: {plan.prompt}",
        f"planner: {plan.planner}, seed {plan.seed}, scene type {plan.scene_type}",
    ]
    if plan.scene_type_match:
        facts.append(f"scene type chosen: {plan.scene_type_match}")
    notes = "".join(f"<li>{escape(n)}</li>" for n in plan.notes) or "<li>none</li>"
    head = "".join(f"<li>{escape(f)}</li>" for f in facts)
    return f"<h2>Request and planner</h2><ul>{head}</ul><h3>Planner notes</h3><ul>{notes}</ul>"


def _import_notes(imported: Any) -> str:
    if not isinstance(imported, dict):
        return ""
    items = [f"format: {imported.get('format', '?')}"]
    for sub in imported.get("substitutions") or []:
        if isinstance(sub, dict):
            items.append(
                f"{sub.get('object_id')}: {sub.get('requested_asset')} replaced by "
                f"{sub.get('used_asset')} ({sub.get('reason')})"
            )
    items += [f"warning: {w}" for w in imported.get("warnings") or []]
    sim = imported.get("simulation_warnings") or {}
    items += [f"smoke-run MuJoCo warning {k}: {v}" for k, v in sorted(sim.items())]
    lis = "".join(f"<li>{escape(str(i))}</li>" for i in items)
    return f"<h2>Import</h2><ul>{lis}</ul>"


def _render_facts(manifest: Mapping[str, Any] | None) -> str:
    if manifest is None:
        return ""
    options = manifest.get("options", {})
    total = manifest.get("timings_s", {}).get("total")
    text = (
        f"rendered at {options.get('width')}×{options.get('height')} with "
        f"MUJOCO_GL={manifest.get('backend')} ({manifest.get('gl_renderer')}), shadows "
        f"{'on' if options.get('shadows') else 'off'}"
    )
    if total is not None:
        text += f", {total:.2f} s"
    return f'<p class="sub">{escape(text)}</p>'
