"""The stability report of ``holomj validate``: pure, frozen, versioned data.

Units: metres, degrees, seconds. Every object of the scene appears in ``objects`` with its
numbers, stable or not; ``reasons`` says in words why an object is not stable.

**Stable**, one definition (``STABILITY_RULE``): an object is stable when

(a) it is at rest at the end: its centre of mass moves less than ``drift_m`` and it turns less
    than ``rotation_deg`` over the monitor window;
(b) its final pose is within ``displacement_m`` and ``rotation_from_authored_deg`` of the pose
    it was authored at (t = 0), after the allowed settle: the centre of mass may first sink up to
    ``settle_drop_m`` (a dropped object falling onto its support);
(c) it is in no penetration deeper than ``tolerance_m`` at t = 0 (its own deepest pair), does
    not end below the floor or outside its room, rests on the support the scene names, and the
    simulation raised no MuJoCo warning;
(d) its moving parts (doors, drawers, lids of articulated objects) end within
    ``part_rotation_deg`` (hinges) and ``part_travel_m`` (slides) of their authored joint values:
    a door that swings open by itself makes its object unstable.

Positions are those of the centre of mass and rotations those of the body, so the rule is the
same whatever the body frame (centre or foot): a footed pole that topples has turned 90°.
"""

from __future__ import annotations

from typing import Annotated, Final, Literal

from pydantic import Field

from holomj.spec.base import FrozenModel, Vec3

REPORT_SCHEMA_VERSION: Final = "2.0"

STABILITY_RULE = (
    "stable = (a) at rest: centre of mass moves < drift_m and body turns < rotation_deg over the "
    "monitor window; (b) final pose within displacement_m and rotation_from_authored_deg of the "
    "authored pose at t = 0 (the centre of mass may first sink up to settle_drop_m onto its "
    "support); (c) no penetration deeper than tolerance_m at t = 0, not below the floor, not "
    "outside its room, on its intended support, no MuJoCo warning; (d) moving parts (doors, "
    "drawers, lids) end within part_rotation_deg (hinges) and part_travel_m (slides) of their "
    "authored joint values. Whatever the body frame."
)

NonNegative = Annotated[float, Field(ge=0.0)]


class Thresholds(FrozenModel):
    """Every limit the validation uses, so a report says what it was judged against."""

    tolerance_m: NonNegative = Field(
        default=0.001, description="Penetration at t = 0 deeper than this is a defect."
    )
    drift_m: NonNegative = Field(
        default=0.01, description="(a) At rest: the centre of mass moves less over the monitor."
    )
    rotation_deg: NonNegative = Field(
        default=5.0, description="(a) At rest: the body turns less over the monitor window."
    )
    displacement_m: NonNegative = Field(
        default=0.02, description="(b) The final centre of mass lies closer to the authored one."
    )
    rotation_from_authored_deg: NonNegative = Field(
        default=5.0, description="(b) The final orientation is closer to the authored one."
    )
    settle_drop_m: NonNegative = Field(
        default=0.01,
        description="(b) The centre of mass may sink this much before displacement counts.",
    )
    fall_m: NonNegative = Field(
        default=0.05, description="Fell: the centre of mass ends this much below t = 0."
    )
    below_floor_m: NonNegative = Field(
        default=0.01, description="Fell through: lowest collider point below -this at the end."
    )
    room_margin_m: NonNegative = Field(
        default=0.05, description="An object within this distance of its room counts as inside."
    )
    rest_linear_mps: NonNegative = Field(default=0.005, description="At rest: slower than this.")
    rest_angular_rps: NonNegative = Field(default=0.05, description="At rest: turns slower.")
    rest_window_s: NonNegative = Field(
        default=0.25, description="Settled: every free body at rest for this long."
    )
    settle_cap_s: NonNegative = Field(default=5.0, description="Most time spent settling.")
    monitor_s: NonNegative = Field(default=3.0, description="Window the numbers are taken over.")
    repair_max_m: NonNegative = Field(
        default=0.05, description="--repair resolves penetrations up to this depth."
    )
    part_rotation_deg: NonNegative = Field(
        default=2.0, description="(d) A hinged part ends closer to its authored angle."
    )
    part_travel_m: NonNegative = Field(
        default=0.005, description="(d) A sliding part ends closer to its authored position."
    )


class ObjectReport(FrozenModel):
    """One object: how it moved from its authored pose, how it behaved over the monitor window,
    and why it is not stable (see ``STABILITY_RULE``)."""

    name: str
    stable: bool
    dynamic: bool = Field(description="Simulated free (a free joint in the validated model).")
    displacement_m: NonNegative = Field(
        description="(b) Distance of the final centre of mass from the authored one, after the "
        "allowed settle drop."
    )
    rotation_from_authored_deg: NonNegative = Field(
        description="(b) Angle between the final and the authored orientation."
    )
    drift_m: NonNegative = Field(
        description="(a) Distance the centre of mass moved over the monitor window."
    )
    rotation_deg: NonNegative = Field(description="(a) Rotation over the monitor window.")
    path_m: NonNegative = Field(description="Path length over the monitor window (jitter).")
    drop_m: float = Field(
        description="Height the centre of mass lost from t = 0 to the end (negative: rose)."
    )
    fell: bool
    left_room: bool
    support: str | None = Field(
        description="What it rests on at the end: an object id, 'floor' (ground and structure), "
        "'fixed' for a static object, None when nothing holds it up."
    )
    expected_support: str | None = Field(
        description="The scene's support ('floor' when none); None: anything will do."
    )
    penetration_m: NonNegative = Field(
        description="(c) Depth of this object's deepest interpenetrating pair at t = 0 (the "
        "audit's, the same number as in ``penetrations``)."
    )
    contact_depth_m: NonNegative = Field(
        default=0.0, description="Deepest contact during the monitor window (solver softness)."
    )
    at_rest: bool
    part_motion: dict[str, NonNegative] = Field(
        default_factory=dict,
        description="(d) Per joint of a moving part (door, drawer, lid): how far it ends from its "
        "authored value, degrees for hinges and metres for slides; empty for rigid objects.",
    )
    reasons: list[str] = Field(default_factory=list)


class PenetrationPair(FrozenModel):
    """Two things that overlap at t = 0 more than the tolerance (the deepest geom pair)."""

    a: str
    b: str
    geom_a: str
    geom_b: str
    depth_m: NonNegative


class ObjectDefect(FrozenModel):
    """An object in a wrong place at t = 0 (below the floor, outside every room)."""

    name: str
    value_m: float = Field(
        description="Below floor: lowest collider z; outside: distance to the nearest room."
    )


class RepairAction(FrozenModel):
    """An object ``--repair`` moved, and by how much."""

    name: str
    moved_m: NonNegative
    translation: Vec3
    rotation_deg: NonNegative = 0.0
    why: str


class Unsaved(FrozenModel):
    """An object ``--repair`` could not fix; it stays in the scene."""

    name: str
    why: str


class StabilityReport(FrozenModel):
    """Everything ``holomj validate`` found about a scene.

    An object is stable when (a) it is at rest at the end (its centre of mass moves less than
    ``thresholds.drift_m`` and it turns less than ``thresholds.rotation_deg`` over the monitor
    window), (b) its final pose is within ``thresholds.displacement_m`` and
    ``thresholds.rotation_from_authored_deg`` of its authored pose at t = 0 (its centre of mass
    may first sink up to ``thresholds.settle_drop_m`` onto its support), and (c) it is in no
    penetration deeper than ``thresholds.tolerance_m`` at t = 0, does not end below the floor or
    outside its room, rests on its intended support, and MuJoCo raised no warning, and (d) its
    moving parts end within ``thresholds.part_rotation_deg`` / ``thresholds.part_travel_m`` of
    their authored joint values. Centre of mass and body orientation make the rule independent
    of the body frame (centre or foot).
    ``ok``: every object stable and nothing found by the audit at t = 0.
    """

    schema_version: Literal["2.0"] = REPORT_SCHEMA_VERSION
    ok: bool = Field(
        description="Every object stable (see stability_rule), no penetration, object below the "
        "floor or outside the rooms at t = 0, and no MuJoCo warning."
    )
    stability_rule: str = STABILITY_RULE
    source: str
    furniture: str = Field(
        default="free",
        description="free: furniture simulated free; static: furniture fixed; as-is: the "
        "scene's own flags (holomj generate: free but for bolted-down fixtures).",
    )
    objects: list[ObjectReport]
    static_objects: list[str] = Field(
        default_factory=list,
        description="Objects simulated fixed (no free joint): not put to the stability test.",
    )
    penetrations: list[PenetrationPair] = Field(default_factory=list)
    below_floor: list[ObjectDefect] = Field(default_factory=list)
    outside_rooms: list[ObjectDefect] = Field(default_factory=list)
    max_penetration_m: NonNegative = Field(
        default=0.0,
        description="Deepest interpenetrating pair at t = 0 (the largest of the objects' "
        "penetration_m and of penetrations[].depth_m).",
    )
    max_contact_depth_m: NonNegative = Field(
        default=0.0, description="Deepest contact of any object during the monitor window."
    )
    warnings: dict[str, int] = Field(default_factory=dict)
    counts: dict[str, int] = Field(default_factory=dict)
    sim_time_s: NonNegative = 0.0
    wall_time_s: NonNegative = 0.0
    realtime_factor: NonNegative = 0.0
    settle_time_s: NonNegative = Field(default=0.0, description="Sim time until at rest.")
    settled: bool = Field(default=True, description="At rest before the settle cap.")
    monitor_s: NonNegative = 0.0
    thresholds: Thresholds = Field(default_factory=Thresholds)
    repaired: list[RepairAction] = Field(default_factory=list)
    unsaved: list[Unsaved] = Field(default_factory=list)

    def unstable(self) -> list[ObjectReport]:
        """The objects that are not stable."""
        return [o for o in self.objects if not o.stable]
