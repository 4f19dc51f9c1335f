"""Physical defaults per category (``data/categories.json``) and the asset's mass.

The table holds materials (density of the material itself, and a wall thickness) and, per
category, a material (with optional overrides), sliding friction, placement flags, an
``upright`` flag and a plausible mass range. Unknown categories get the table's ``default``
entry, with placement ``["object"]`` for assets under :data:`SMALL_OBJECT_M` and ``["floor"]``
otherwise.

Mass, in order of precedence:

1. a given mass (import option or sidecar ``mass_kg``), never changed;
2. a sidecar ``density_kg_m3``: that density x the collision volume (the meaning of
   :attr:`~holomj.spec.assets.AssetMeta.density_kg_m3`);
3. otherwise the **material estimate**: material density x :func:`material_volume` of the
   physics mesh. Convex hulls are not used: they fill hollow and open things (a bookcase's
   hull is mostly air), and their volume depends on the decomposition settings.

A mass outside the category's plausible range is reported as a warning; an *estimated* mass
is also clamped to the range, and the clamp and its reason are recorded in the derivation.
"""

from __future__ import annotations

import functools
import json
import math
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError

from asset_pipeline.decompose import bodies
from holomj.spec.categories import normalise_category

SMALL_OBJECT_M = 0.6
DEFAULT_CATEGORY = "object"
NEARLY_CLOSED_TOL = 0.1  # spread of the signed volume over origins, relative to it


@dataclass(frozen=True)
class PhysicalDefaults:
    """One category's physical defaults.

    ``density_kg_m3`` is the density of the category's material itself (oak, sheet steel,
    the contents of a full can); ``wall_m`` is its skin thickness for the material volume
    estimate, None for things counted solid (fruit, books, upholstery).
    """

    name: str
    known: bool
    material: str
    density_kg_m3: float
    wall_m: float | None
    friction: float
    placement: tuple[str, ...]
    upright: bool
    mass_range_kg: tuple[float, float]


@dataclass(frozen=True)
class MaterialVolume:
    """How much material a mesh holds, body by body (see :func:`material_volume`)."""

    volume_m3: float
    surface_area_m2: float
    model_volume_m3: float
    closed_bodies: int
    nearly_closed_bodies: int
    holes_filled: int
    open_bodies: int
    hollowed_bodies: int

    def as_dict(self) -> dict[str, Any]:
        """JSON-able form for the derivation record."""
        return {
            "material_volume_m3": self.volume_m3,
            "surface_area_m2": self.surface_area_m2,
            "model_volume_m3": self.model_volume_m3,
            "closed_bodies": self.closed_bodies,
            "nearly_closed_bodies": self.nearly_closed_bodies,
            "bodies_closed_by_filling_holes": self.holes_filled,
            "open_bodies": self.open_bodies,
            "bodies_hollowed_to_wall": self.hollowed_bodies,
        }


@dataclass(frozen=True)
class MassResult:
    """The mass, one line saying how it was found, the derivation record and warnings."""

    mass_kg: float
    source: str
    derivation: dict[str, Any]
    warnings: list[str]


@functools.cache
def _table() -> dict:
    text = resources.files("asset_pipeline").joinpath("data/categories.json").read_text("utf-8")
    return json.loads(text)


def categories() -> list[str]:
    """All category names of the table, sorted."""
    return sorted(_table()["categories"])


def materials() -> list[str]:
    """All material names of the table, sorted."""
    return sorted(k for k in _table()["materials"] if not k.startswith("_"))


def category_info(name: str, size: tuple[float, float, float] | None = None) -> PhysicalDefaults:
    """The table's entry for ``name`` (case and separators ignored), else the default."""
    key = normalise_category(name)
    for category, row in _table()["categories"].items():
        if normalise_category(category) == key:
            return _info(category, row, known=True, placement=tuple(row["placement"]))
    row = _table()["default"]
    small = size is None or max(size) < SMALL_OBJECT_M
    return _info(name, row, known=False, placement=("object",) if small else ("floor",))


def _info(name: str, row: dict, known: bool, placement: tuple[str, ...]) -> PhysicalDefaults:
    material = _table()["materials"][row["material"]]
    return PhysicalDefaults(
        name=name,
        known=known,
        material=row["material"],
        density_kg_m3=float(row.get("density_kg_m3", material["density_kg_m3"])),
        wall_m=row.get("wall_m", material["wall_m"]),
        friction=row["friction"],
        placement=placement,
        upright=row["upright"],
        mass_range_kg=tuple(row["mass_range_kg"]),
    )


def guess_category(path: Path) -> str | None:
    """A category named in the file name, else in its folder's name (longest match wins).

    Names and aliases match as whole ``_``-separated words, so ``coffee_table.glb`` is a
    coffee_table, ``bedside_table_01.glb`` a nightstand and ``ycb_005_tomato_soup_can/
    textured.obj`` a can. A trailing plural ``s`` is ignored.
    """
    for text in (path.stem, path.parent.name):
        best = _best_match(_words(text))
        if best is not None:
            return best
    return None


def material_volume(mesh: trimesh.Trimesh, wall_m: float | None) -> MaterialVolume:
    """Estimate the volume of real material in ``mesh`` (oriented outward, metres).

    Body by body (faces connected through shared vertices; see :func:`_body_volume`):

    * a closed body (watertight; or closed by filling its triangle and quad holes, as a board
      modelled without its end faces; or open with holes that let almost no volume out) has
      its *enclosed volume*: the mesh's own volume, never its hull's;
    * an open body (a single-sided surface, a scan with holes) has no enclosed volume; the
      volume of its convex hull bounds it from above.

    With a wall thickness, each body keeps only a skin of ``wall_m`` under its outward-facing
    surface: min(volume, skin). Parts thinner than about twice the wall (a shelf board, a
    fork) keep their whole volume; a sphere modelled for a hollow globe or a block modelled
    for a cabinet counts as its walls; a model with inner and outer walls (a double-sided
    shell, which fills little of its hull) gets one real wall per pair; an open surface counts
    as a sheet ``wall_m`` thick under its faces on the body's hull (the inner side of a
    double-sided open model is not). Without a wall thickness (solids), the volume as it is.
    Open frames (shelving) count the volume of their parts, never the air between them.
    """
    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    faces_all = np.asarray(mesh.faces)
    total = area_total = model_total = 0.0
    closed = nearly = filled = opened = hollowed = 0
    for faces in bodies(mesh):
        used, local = np.unique(faces_all[faces], return_inverse=True)
        body = trimesh.Trimesh(vertices[used], local.reshape(-1, 3), process=False)
        area = float(body.area)
        model, kind, hull_volume = _body_volume(body)
        closed += kind == "closed"
        nearly += kind == "nearly closed"
        filled += kind == "filled"
        opened += kind == "open"
        volume = model
        if wall_m is not None:
            if kind == "open":
                # A sheet wall_m thick under the part of the surface on the body's hull (an
                # inner wall of a double-sided model is not); a flat sheet has no hull volume.
                skin = area * wall_m
                if hull_volume > skin * 1e-3:
                    skin *= _on_hull_share(body, wall_m / 2)
                    volume = min(skin, hull_volume)
                else:
                    volume = skin
            else:
                # Outward-facing share of the surface: all of it for a solid block, about
                # half for a model with inner and outer walls (which fills little of its
                # hull), so a modelled wall pair gets one real wall.
                fill = min(1.0, model / hull_volume) if hull_volume > 0 else 1.0
                skin = area * wall_m * (1.0 + fill) / 2.0
                if skin < model:
                    hollowed += 1
                    volume = skin
        total += volume
        area_total += area
        model_total += model
    return MaterialVolume(
        volume_m3=total,
        surface_area_m2=area_total,
        model_volume_m3=model_total,
        closed_bodies=closed,
        nearly_closed_bodies=nearly,
        holes_filled=filled,
        open_bodies=opened,
        hollowed_bodies=hollowed,
    )


def _body_volume(body: trimesh.Trimesh) -> tuple[float, str, float]:
    """(volume, kind, convex hull volume) of one body.

    kind "closed": watertight with consistent winding; "filled": closed once its triangle
    and quad holes are filled; "nearly closed": open, but its signed volume hardly depends on
    the origin it is taken from (the holes let almost no volume out), so it is used; the
    volume of these is the enclosed volume. Else "open", with the hull volume as the volume.
    """
    points = np.asarray(body.vertices)
    try:
        hull_volume = float(ConvexHull(points).volume)
    except (QhullError, ValueError):
        hull_volume = 0.0  # flat
    if body.is_watertight and body.is_winding_consistent:
        return abs(float(body.volume)), "closed", hull_volume
    patched = body.copy()
    trimesh.repair.fill_holes(patched)
    if patched.is_watertight and patched.is_winding_consistent:
        return abs(float(patched.volume)), "filled", hull_volume
    if body.is_winding_consistent and hull_volume > 0:
        lo, hi = body.bounds
        signed = [_signed_volume(body, origin) for origin in (lo, hi, (lo + hi) / 2)]
        mean = float(np.mean(signed))
        if mean > 0 and max(signed) - min(signed) <= NEARLY_CLOSED_TOL * mean:
            return min(mean, hull_volume), "nearly closed", hull_volume
    return hull_volume, "open", hull_volume


def _on_hull_share(body: trimesh.Trimesh, tol: float) -> float:
    """The share of ``body``'s area whose faces lie on its convex hull's boundary (within
    ``tol``): 1 for a single-sided sheet or a convex surface, about a half for a model of a
    wall with an inner and an outer side."""
    try:
        equations = ConvexHull(np.asarray(body.vertices)).equations
    except (QhullError, ValueError):
        return 1.0
    centres = np.asarray(body.triangles_center)
    depth = (centres @ equations[:, :3].T + equations[:, 3]).max(axis=1)
    areas = np.asarray(body.area_faces)
    total = float(areas.sum())
    return float(areas[depth >= -tol].sum()) / total if total > 0 else 1.0


def _signed_volume(body: trimesh.Trimesh, origin: np.ndarray) -> float:
    """Signed volume of the cones from ``origin`` to the faces (origin-free when closed)."""
    tri = np.asarray(body.triangles) - origin
    return float(np.einsum("ij,ij->i", tri[:, 0], np.cross(tri[:, 1], tri[:, 2])).sum() / 6.0)


def resolve_mass(
    info: PhysicalDefaults,
    mesh: trimesh.Trimesh,
    collision_volume: float,
    given: float | None = None,
    density: float | None = None,
) -> MassResult:
    """The asset's mass (see the module docstring for the rules) and how it was derived.

    ``given``: a mass from the caller or the sidecar; ``density``: a sidecar density of the
    collision volume. The derivation record is JSON-able and says which rule applied, with
    the numbers that went in.
    """
    lo, hi = info.mass_range_kg
    record: dict[str, Any] = {
        "category": info.name,
        "category_known": info.known,
        "plausible_range_kg": [lo, hi],
        "collision_volume_m3": collision_volume,
    }
    warnings: list[str] = []
    if given is not None:
        mass, source = float(given), "given"
        record.update(method="given")
    elif density is not None:
        mass, source = density * collision_volume, "sidecar density x collision volume"
        record.update(method="density x collision volume", density_kg_m3=density)
    else:
        measured = material_volume(mesh, info.wall_m)
        estimate = info.density_kg_m3 * measured.volume_m3
        source = "material density x material volume"
        record.update(
            method="material density x material volume",
            material=info.material,
            material_density_kg_m3=info.density_kg_m3,
            wall_m=info.wall_m,
            **measured.as_dict(),
            estimate_kg=estimate,
        )
        mass = estimate
        if not lo <= estimate <= hi or not math.isfinite(estimate):
            finite = math.isfinite(estimate)
            mass = min(max(estimate, lo), hi) if finite else hi
            side = "outside" if not finite else "below" if estimate < lo else "above"
            reason = (
                f"the material estimate {estimate:.4g} kg is {side} the plausible range "
                f"{lo:g}-{hi:g} kg of category {info.name!r}"
            )
            if not finite:
                record["estimate_kg"] = None  # JSON has no NaN
            record.update(clamped=True, clamp_reason=f"{reason}; clamped to {mass:g} kg")
            warnings.append(
                f"mass clamped to {mass:g} kg: {reason} (check the size/units and the "
                "category, or give mass_kg)"
            )
            source += f", clamped to the range of {info.name!r}"
        else:
            record.update(clamped=False)
    if source in ("given", "sidecar density x collision volume") and not lo <= mass <= hi:
        warnings.append(
            f"mass {mass:.4g} kg ({source}) is outside the plausible range {lo:g}-{hi:g} kg "
            f"of category {info.name!r}: check the size/units or give mass_kg"
        )
    record.update(mass_kg=mass, source=source)
    return MassResult(mass_kg=mass, source=source, derivation=record, warnings=warnings)


def _words(text: str) -> list[str]:
    words = [w for w in re.split(r"[^a-z]+", text.lower()) if w]
    return [w[:-1] if len(w) > 3 and w.endswith("s") and not w.endswith("ss") else w for w in words]


@functools.cache
def _names() -> list[tuple[tuple[str, ...], str]]:
    """(words of a name or alias, category), longest first."""
    out = []
    for category, row in _table()["categories"].items():
        for name in [category, *row.get("aliases", [])]:
            out.append((tuple(_words(name)), category))
    return sorted(out, key=lambda item: (-len(item[0]), item[0], item[1]))


def _best_match(words: list[str]) -> str | None:
    for name, category in _names():
        n = len(name)
        if n and any(tuple(words[i : i + n]) == name for i in range(len(words) - n + 1)):
            return category
    return None
