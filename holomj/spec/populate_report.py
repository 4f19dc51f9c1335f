"""``populate_report.json``: what ``holomj populate`` did to a scene folder, one run and the
history of the runs before it (see :mod:`holomj.jobs.populate`)."""

from __future__ import annotations

from typing import Any

from holomj.spec.base import FrozenModel


class RequestedCount(FrozenModel):
    """One request: a category or asset id and how many of it."""

    name: str
    count: int


class PopulateValidation(FrozenModel):
    """The validation of the populated scene, when the folder had one (``report.json``)."""

    ok: bool
    furniture: str
    counts: dict[str, int]


class PopulateRun(FrozenModel):
    """One run of populate. Fields a run does not have (the drop timings of a pointing run,
    the model's records of a drop run, the instruction when none was given, ...) are left
    unset and left out of its JSON."""

    receptacle: str
    requests: list[RequestedCount]
    drawn_from: str | None  # "instruction", "llm pointing", the priors' source, None: asked
    seed: int
    max_attempts: int
    requested: int
    placed: int
    receptacle_drift_m: float | None = None  # drops: how far the receptacle moved
    seconds: float | None = None  # drops: how long they took
    placements: list[dict[str, Any]]  # per object: object_id, asset, accepted, reason, ...
    pointing: list[dict[str, Any]] | None = None  # the model's records, as it gave them
    llm: dict[str, Any] | None = None  # model, images, text_only_reason and the usage
    instruction: str | None = None
    planner: str | None = None  # with an instruction: "llm" or "offline"
    notes: list[str] | None = None
    validation: PopulateValidation | None = None

    def to_dict(self) -> dict[str, Any]:
        """The run as ``populate_report.json`` holds it (the fields it has, in field order)."""
        return self.model_dump(exclude_unset=True)


class PopulateReport(PopulateRun):
    """The last run, the history of every run (earlier ones as read back from the folder's
    report) and the files that still show the scene before it."""

    runs: list[dict[str, Any]]
    stale_files: list[str]
