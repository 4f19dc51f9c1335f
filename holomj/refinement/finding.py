"""A finding of the evaluation that moving one object can fix (made by
:mod:`holomj.jobs.refine_findings`, read by the refine planners)."""

from __future__ import annotations

from dataclasses import asdict, dataclass


@dataclass(frozen=True)
class Finding:
    """The metric that found it, the object to move and why (``blocks door_0``)."""

    metric: str
    object: str
    reason: str

    def to_json(self) -> dict[str, str]:
        """JSON-able form (for refine.json)."""
        return asdict(self)

    def line(self) -> str:
        """One line for a model's prompt: ``doors_clear: kitchen.table_0 blocks door_0``."""
        return f"{self.metric}: {self.object} {self.reason}"
