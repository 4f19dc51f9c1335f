"""One seed, one generator per stage: the only place where seeds become generators.

Each stage draws from its own stream, so changing how much randomness one stage uses (say, the
layout solver) never shifts the draws of another (say, which small objects go on a table). A job
with a single random stage (``holomj populate``, ``holomj layout solve``) draws from
:func:`seed_rng`.
"""

from __future__ import annotations

import zlib

import numpy as np

MAX_SEED = 2**32 - 1


def stage_rng(seed: int, stage: str, *keys: str) -> np.random.Generator:
    """The generator of ``stage`` (and optional sub-keys, e.g. a room id) for ``seed``."""
    words = [int(seed)] + [zlib.crc32(part.encode("utf-8")) for part in (stage, *keys)]
    return np.random.default_rng(np.random.SeedSequence(words))


def seed_rng(seed: int) -> np.random.Generator:
    """The generator of a job that has a single random stage."""
    if int(seed) < 0:
        raise ValueError(f"seeds are >= 0, got {seed}")
    return np.random.default_rng(int(seed))
