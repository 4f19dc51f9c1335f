"""The objects table of the report page (:mod:`holomj.rendering.report_html`): each object's
room, category, asset, size, mass, kind, support and verdict, and the same facts for the 3D
view's labels."""

from __future__ import annotations

from html import escape
from typing import Any

from holomj.library.store import AssetLibrary
from holomj.spec.report import ObjectReport, StabilityReport
from holomj.spec.scene import SceneObject, SceneSpec


def object_table(scene: SceneSpec, library: AssetLibrary, report: StabilityReport | None) -> str:
    """The report page's table of objects: where each is, what it is, and its verdict."""
    by_name = {o.name: o for o in report.objects} if report is not None else {}
    heads = [
        "object",
        "room",
        "category",
        "asset",
        "size w×d×h (m)",
        "mass (kg)",
        "kind",
        "support",
        "stable",
        "moved (mm)",
        "turned (°)",
        "notes",
    ]
    rows = [
        _object_row(obj, library, by_name.get(obj.id), report is not None) for obj in scene.objects
    ]
    if not rows:
        return "<h2>Objects</h2><p>The scene has no objects.</p>"
    head = "".join(f"<th>{escape(h)}</th>" for h in heads)
    return (
        f'<h2>Objects</h2><table id="objects"><thead><tr>{head}</tr></thead>'
        f"<tbody>{''.join(rows)}</tbody></table>"
    )


def object_facts(
    obj: SceneObject, library: AssetLibrary, result: ObjectReport | None, validated: bool
) -> dict[str, Any]:
    """What the table and the 3D view say about one object (numbers unformatted)."""
    facts: dict[str, Any] = {
        "room": obj.room,
        "asset": obj.asset,
        "category": None,
        "size": None,
        "mass_kg": None,
        # what the validation simulated, when known; else the scene's flag
        "static": not result.dynamic if result is not None else bool(obj.static),
        "support": obj.support,
    }
    if obj.asset in library:
        meta = library.get(obj.asset).meta
        sx, sy, sz = obj.scale3
        proxy = meta.proxy or obj.proxy
        facts["category"] = f"{meta.category} (proxy)" if proxy else meta.category
        facts["size"] = (meta.size[0] * sx, meta.size[1] * sy, meta.size[2] * sz)
        facts["mass_kg"] = obj.mass_kg if obj.mass_kg is not None else meta.mass * sx * sy * sz
    if result is not None:
        facts["stable"] = result.stable
        facts["verdict"] = "stable" if result.stable else "not stable"
        facts["reasons"] = list(result.reasons)
        facts["moved_mm"] = result.displacement_m * 1000
        facts["turned_deg"] = result.rotation_from_authored_deg
    else:
        facts["verdict"] = "not in report" if validated else "not validated"
    return facts


def _object_row(
    obj: SceneObject, library: AssetLibrary, result: ObjectReport | None, validated: bool
) -> str:
    facts = object_facts(obj, library, result, validated)
    category = facts["category"] or "?"
    size = "?" if facts["size"] is None else " × ".join(f"{v:.2f}" for v in facts["size"])
    mass = "?" if facts["mass_kg"] is None else f"{facts['mass_kg']:.2f}"
    if result is not None:
        stable = "yes" if result.stable else "no"
        # how far it ended from its authored pose (rule (b) of the stability rule)
        drift = f"{facts['moved_mm']:.2f}"
        rotation = f"{facts['turned_deg']:.2f}"
        notes = "; ".join(result.reasons)
    else:
        stable = facts["verdict"]
        drift = rotation = notes = "—"
    css = ' class="unstable"' if result is not None and not result.stable else ""
    cells = [
        (obj.id, ""),
        (obj.room or "—", ""),
        (category, ""),
        (obj.asset, ""),
        (size, "num"),
        (mass, "num"),
        ("static" if facts["static"] else "free", ""),
        (obj.support or "floor", ""),
        (stable, ""),
        (drift, "num"),
        (rotation, "num"),
        (notes, ""),
    ]
    tds = "".join(
        f'<td class="{c}">{escape(str(v))}</td>' if c else f"<td>{escape(str(v))}</td>"
        for v, c in cells
    )
    return f"<tr{css}>{tds}</tr>"
