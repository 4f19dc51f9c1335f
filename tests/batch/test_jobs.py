"""The jobs file: prompts and house paths, comments, seeds, ids, and one-line errors."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from holomj.batch.job_list import MAX_PROMPT_CHARS, job_id, parse_seeds, read_jobs
from holomj.errors import InputError
from holomj.jobs import generate as runner


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_prompts_and_house_files_comments_and_blank_lines(tmp_path: Path) -> None:
    (tmp_path / "houses").mkdir()
    (tmp_path / "houses" / "House 12.json").write_text("{}")
    jobs_file = write(
        tmp_path / "jobs.txt",
        "# my batch\n\n  a small kitchen  \nhouses/House 12.json\n   # indented comment\n"
        "A Music Room, with a PIANO!\n",
    )
    jobs = read_jobs(jobs_file, parse_seeds("3:5"))
    assert [(j.id, j.kind, j.seed) for j in jobs] == [
        ("0003-a_small_kitchen-s3", "prompt", 3),
        ("0003-a_small_kitchen-s4", "prompt", 4),
        ("0004-house_12", "house", None),
        ("0006-a_music_room_with_a_piano-s3", "prompt", 3),
        ("0006-a_music_room_with_a_piano-s4", "prompt", 4),
    ]
    assert jobs[0].input == "a small kitchen"
    assert jobs[2].input == str((tmp_path / "houses" / "House 12.json").resolve())
    assert read_jobs(jobs_file, parse_seeds("3:5")) == jobs  # deterministic


def test_default_seed_is_zero_and_ids_are_filesystem_safe(tmp_path: Path) -> None:
    jobs_file = write(tmp_path / "jobs.txt", "../../etc/passwd? *x* | rm -rf /\n¿¡!!\n" + "w " * 40)
    jobs = read_jobs(jobs_file)
    assert [j.seed for j in jobs] == [0, 0, 0]
    for job in jobs:
        assert re.fullmatch(r"[0-9]{4}-[a-z0-9_]{1,40}-s0", job.id), job.id
    assert jobs[1].id == "0002-job-s0"
    assert len({j.id for j in jobs}) == 3


def test_job_id_shape() -> None:
    assert job_id(7, "A small kitchen", 12) == "0007-a_small_kitchen-s12"
    assert job_id(12345, "house_3", None) == "12345-house_3"


@pytest.mark.parametrize(
    ("text", "expected"),
    [(None, range(0, 1)), ("0:4", range(0, 4)), (" 7 : 9 ", range(7, 9)), ("5", range(5, 6))],
)
def test_parse_seeds(text: str | None, expected: range) -> None:
    assert parse_seeds(text) == expected


@pytest.mark.parametrize(
    "text", ["", "a:b", "4:4", "5:2", "-1:3", "0:4:1", "1.5:3", "0:9999999999"]
)
def test_bad_seeds_are_input_errors(text: str) -> None:
    with pytest.raises(InputError) as err:
        parse_seeds(text)
    assert "--seeds" in str(err.value) and "\n" not in str(err.value)


def test_missing_empty_unreadable_and_folder_jobs_files(tmp_path: Path) -> None:
    cases = {
        tmp_path / "missing.txt": "not found",
        write(tmp_path / "empty.txt", ""): "no jobs",
        write(tmp_path / "comments.txt", "# only\n\n   \n# comments\n"): "no jobs",
        tmp_path: "is a folder",
    }
    binary = tmp_path / "binary.txt"
    binary.write_bytes(b"\xff\xfe\x00bad")
    cases[binary] = "not UTF-8"
    for path, message in cases.items():
        with pytest.raises(InputError) as err:
            read_jobs(path)
        assert message in str(err.value) and str(path) in str(err.value)
        assert err.value.exit_code == 2


def test_missing_house_file_names_the_line(tmp_path: Path) -> None:
    jobs_file = write(tmp_path / "jobs.txt", "a kitchen\nnope/house.json\n")
    with pytest.raises(InputError, match=r"line 2: house JSON file not found: nope/house.json"):
        read_jobs(jobs_file)


def test_overlong_prompt_is_rejected_with_its_line(tmp_path: Path) -> None:
    assert MAX_PROMPT_CHARS == runner.MAX_PROMPT_CHARS
    jobs_file = write(tmp_path / "jobs.txt", "ok\n" + "x" * (MAX_PROMPT_CHARS + 1) + "\n")
    with pytest.raises(InputError, match="line 2"):
        read_jobs(jobs_file)
