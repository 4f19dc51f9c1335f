"""One seed, one generator per stage: the only place where seeds become generators.

Each stage draws from its own stream, so changing how much randomness one stage uses (say, the
layout solver) never shifts the draws of another (say, which small objects go on a table).
"""

from __future__ import annotations

import zlib

import numpy as np

MAX_SEED = 2**32 - 1


def stage_rng(seed: int, stage: str, *keys: str) -> np.random.Generator:
    """The generator of ``stage`` (and optional sub-keys, e.g. a room id) for ``seed``."""
    words = [int(seed)] + [zlib.crc32(part.encode("utf-8")) for part in (stage, *keys)]
    return np.random.default_rng(np.random.SeedSequence(words))
