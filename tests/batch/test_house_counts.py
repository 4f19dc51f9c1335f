"""A house job of ``holomj batch`` records what the import changed: objects moved to stand,
left out, substituted (the summary table's house columns)."""

from __future__ import annotations

from pathlib import Path

import pytest

from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions
from holomj.batch.runner import run_job
from holomj.library.store import AssetLibrary

HOUSE = Path(__file__).resolve().parents[3] / "shared" / "procthor" / "houses"
KLBR = HOUSE / "procthor_zhiyuangao_klbr_house_0.json"


def test_a_house_job_counts_moved_left_out_and_substituted(
    tmp_path: Path, default_library: AssetLibrary
) -> None:
    if not KLBR.is_file():
        pytest.skip(f"real house not found at {KLBR}")
    job = Job(id="0001-klbr", line=1, kind="house", input=str(KLBR))
    options = JobOptions(library=default_library.root, check_seconds=0.0)
    result = run_job(job, tmp_path, options)
    assert result.status == "ok"
    assert result.objects == 17 and result.left_out == 0
    assert result.moved is not None and result.moved > 0
    assert result.substituted == 17  # every asset of this house stands in
    assert (tmp_path / "0001-klbr" / "scene.xml").is_file()
