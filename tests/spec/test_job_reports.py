"""The typed job reports write exactly the JSON the dict records wrote: same keys, same order,
optional populate fields only when a run has them."""

from __future__ import annotations

import json

from holomj.spec.export_details import UrdfDetails
from holomj.spec.populate_report import PopulateReport, PopulateRun, RequestedCount
from holomj.spec.stand_record import StandRecord

STAND = {
    "valid": True,
    "moved": [{"object": "a", "moved_m": 0.1, "from": [0, 0, 0], "to": [0.1, 0, 0]}],
    "settled_only": {"count": 1, "max_m": 0.0004},
    "dropped": [],
    "separated": [],
    "reassigned": [],
    "unsaved": [{"object": "b", "why": "stuck"}],
    "penetrations_before": {"count": 2, "max_m": 0.1},
    "penetrations_after": {"count": 0, "max_m": 0.0},
    "validation": None,
    "stand_seconds": {"settle": 0.5},
    "objects_imported": 3,
    "objects_kept": 3,
    "kept_share": 1.0,
    "relocated": [],
    "left_out": [],
    "stand_rounds": 1,
    "refusal": None,
    "allow_invalid": False,
    "strict": False,
}


def test_stand_record_dumps_as_the_record_it_types() -> None:
    record = StandRecord(**STAND)
    assert json.dumps(record.to_dict()) == json.dumps(STAND)
    assert record.valid and record.unsaved[0]["why"] == "stuck"


def test_populate_report_keeps_only_the_fields_a_run_has() -> None:
    run = PopulateRun(
        receptacle="table",
        requests=[RequestedCount(name="mug", count=2)],
        drawn_from=None,
        seed=0,
        max_attempts=20,
        requested=2,
        placed=1,
        receptacle_drift_m=0.0,
        seconds=1.5,
        placements=[{"object_id": "mug_00", "accepted": True}],
    ).model_copy(update={"notes": ["a note"]})
    first = run.to_dict()
    assert list(first) == [
        "receptacle", "requests", "drawn_from", "seed", "max_attempts", "requested", "placed",
        "receptacle_drift_m", "seconds", "placements", "notes",
    ]  # fmt: skip
    report = PopulateReport(**first, runs=[{"older": 1}, first], stale_files=["renders"])
    dumped = report.to_dict()
    assert list(dumped) == [*first, "runs", "stale_files"]
    assert dumped["runs"][1] == first and dumped["drawn_from"] is None


def test_export_details_dump_as_written() -> None:
    assets = [{"urdf": "door/door.urdf", "joints": [{"name": "hinge", "type": "revolute"}]}]
    assert UrdfDetails(assets=assets).model_dump() == {"assets": assets}
