"""What making an imported house stand changed: the compile report's ``stand`` record, also
written into ``import_report.json`` (see :mod:`holomj.physics.standing` for each field)."""

from __future__ import annotations

from typing import Any

from holomj.spec.base import FrozenModel


class StandRecord(FrozenModel):
    """The stand stage's changes and verdict, field for field as ``import_report.json`` holds
    them (the stage's own fields, the keeping stage's, then the compile's decision)."""

    valid: bool  # every object saved, the final validation ok and the house not refused
    moved: list[dict[str, Any]]  # object, moved_m, translation, rotation_deg, why, from, to
    settled_only: dict[str, Any]  # objects settling alone moved (under 1 mm), and the most
    dropped: list[dict[str, Any]]  # object, onto, surface, attempts, from_xy, position, ...
    separated: list[dict[str, Any]]  # object, from (an object or a wall), moved_m, translation
    reassigned: list[dict[str, str]]  # object, field (support or room), value, why
    unsaved: list[dict[str, str]]  # object, why
    penetrations_before: dict[str, Any]  # count, deepest max_m at t = 0
    penetrations_after: dict[str, Any]
    validation: dict[str, Any] | None  # the final verdict in numbers (None: skipped)
    stand_seconds: dict[str, float]  # per step
    objects_imported: int
    objects_kept: int
    kept_share: float
    relocated: list[dict[str, Any]]  # objects moved to another receptacle
    left_out: list[dict[str, Any]]  # objects the written house leaves out
    stand_rounds: int
    refusal: str | None  # why the house would be refused (None: it stands)
    allow_invalid: bool
    strict: bool

    def to_dict(self) -> dict[str, Any]:
        """The record as ``import_report.json`` holds it, in its field order."""
        return self.model_dump()
