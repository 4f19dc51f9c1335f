"""The jobs file: one job per line, a text prompt or the path of a house JSON file.

Blank lines and lines starting with ``#`` are ignored. A line ending in ``.json`` is a house
file, relative to the jobs file's folder (or absolute); it must exist. Every other line is a
prompt. Prompts run once per seed of ``--seeds A:B``; a house file is compiled once (compiling
is deterministic: a seed would change nothing).

Job ids are deterministic and safe as folder names: the line number, a slug of the prompt or of
the file name, and the seed, e.g. ``0003-a_small_kitchen-s7`` or ``0005-house_12``.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Literal

from pydantic import Field

from holomj.errors import InputError
from holomj.spec.base import FrozenModel

MAX_SEED = 2**32 - 1
MAX_SEEDS_PER_LINE = 100_000
MAX_PROMPT_CHARS = 2000  # as holomj.jobs.generate (checked by a test), without its imports
SLUG_WORDS = 6
SLUG_CHARS = 40
SEEDS_FIX = "write A:B with integers 0 <= A < B <= 4294967296, e.g. 0:4 for seeds 0, 1, 2, 3"


class Job(FrozenModel):
    """One unit of work: a prompt with a seed, or a house file."""

    id: str = Field(pattern=r"^[0-9]{4,}-[a-z0-9_]+(-s[0-9]+)?$")
    line: int = Field(ge=1, description="1-based line number in the jobs file.")
    kind: Literal["prompt", "house"]
    input: str = Field(min_length=1, description="The prompt, or the house file's absolute path.")
    seed: int | None = Field(default=None, ge=0, le=MAX_SEED)


def parse_seeds(text: str | None) -> range:
    """``A:B`` as ``range(A, B)``; a single ``N`` means ``N:N+1``; None means seed 0."""
    if text is None:
        return range(0, 1)
    match = re.fullmatch(r"\s*(\d+)\s*(?::\s*(\d+)\s*)?", text)
    if match is None:
        raise InputError(f"bad seed range {text!r}", where="--seeds", fix=SEEDS_FIX)
    start = int(match.group(1))
    stop = int(match.group(2)) if match.group(2) is not None else start + 1
    if start >= stop or stop > MAX_SEED + 1:
        raise InputError(
            f"empty or out-of-range seed range {text!r}", where="--seeds", fix=SEEDS_FIX
        )
    if stop - start > MAX_SEEDS_PER_LINE:
        raise InputError(
            f"{stop - start} seeds per line is too many",
            where="--seeds",
            fix=f"use at most {MAX_SEEDS_PER_LINE}",
        )
    return range(start, stop)


def slug(text: str) -> str:
    """A short lowercase ``a_small_kitchen`` form of ``text`` (``job`` when nothing is left)."""
    words = re.findall(r"[a-z0-9]+", text.lower())[:SLUG_WORDS]
    return "_".join(words)[:SLUG_CHARS].strip("_") or "job"


def job_id(line: int, text: str, seed: int | None) -> str:
    """The id of the job from ``line`` (1-based), its prompt or file stem, and its seed."""
    base = f"{line:04d}-{slug(text)}"
    return base if seed is None else f"{base}-s{seed}"


def read_jobs(path: Path, seeds: range | None = None) -> list[Job]:
    """The jobs of the jobs file at ``path``, in file order, each prompt once per seed."""
    path = Path(path)
    text = _read_text(path)
    seeds = seeds if seeds is not None else range(0, 1)
    jobs: list[Job] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        if line.lower().endswith(".json"):
            house = _house_path(path, line, number)
            jobs.append(
                Job(
                    id=job_id(number, house.stem, None), line=number, kind="house", input=str(house)
                )
            )
            continue
        if len(line) > MAX_PROMPT_CHARS:
            raise InputError(
                f"the prompt has {len(line)} characters, more than {MAX_PROMPT_CHARS}",
                where=f"{path}: line {number}",
            )
        jobs.extend(
            Job(id=job_id(number, line, seed), line=number, kind="prompt", input=line, seed=seed)
            for seed in seeds
        )
    if not jobs:
        raise InputError(
            "no jobs: every line is blank or a comment",
            where=str(path),
            fix="write one prompt or house JSON path per line",
        )
    return jobs


def _read_text(path: Path) -> str:
    """The jobs file's text; a missing, unreadable or binary file is an InputError."""
    try:
        return path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError("jobs file not found", where=str(path)) from None
    except IsADirectoryError:
        raise InputError("is a folder, expected a jobs file", where=str(path)) from None
    except UnicodeDecodeError:
        raise InputError(
            "jobs file is not UTF-8 text", where=str(path), fix="one prompt or path per line"
        ) from None
    except OSError as err:
        raise InputError(
            f"cannot read the jobs file: {err.strerror or err}", where=str(path)
        ) from None


def _house_path(jobs_file: Path, line: str, number: int) -> Path:
    """The absolute path of a house file named on ``line`` (relative to the jobs file)."""
    house = Path(line).expanduser()
    if not house.is_absolute():
        house = jobs_file.parent / house
    if not house.is_file():
        raise InputError(
            f"house JSON file not found: {line}",
            where=f"{jobs_file}: line {number}",
            fix="paths are relative to the jobs file's folder",
        )
    return house.resolve()
