"""The generated kitchen the task tests share."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.tasks.kitchen_scene import generated_kitchen


@pytest.fixture(scope="session")
def kitchen() -> Path:
    """A generated kitchen folder with a Jaco arm (shared with tests/envs)."""
    return generated_kitchen()
