"""One generated kitchen with a robot, shared by the task and environment tests of a session
(generated once per test process: both packages' fixtures call :func:`generated_kitchen`)."""

from __future__ import annotations

import functools
import tempfile
from pathlib import Path

PROMPT = "a kitchen with a fridge, a drawer unit, a sink counter and a mug on the counter"
ROBOT = "jaco"


@functools.cache
def generated_kitchen() -> Path:
    """The folder of a kitchen generated with the default library, seed 0, a Jaco arm."""
    from asset_pipeline.default_library import ensure_default_library
    from holomj.jobs.generate import GenerateOptions, generate_scene

    folder = Path(tempfile.mkdtemp(prefix="holomj-tasks-")) / "kitchen"
    options = GenerateOptions(library=ensure_default_library(), seed=0, render=False, robot=ROBOT)
    result = generate_scene(PROMPT, folder, options)
    assert result.ok, result.report.counts
    return folder
