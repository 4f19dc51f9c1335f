"""The generated kitchen the environment tests share with the task tests (generated once)."""

from tests.tasks.conftest import kitchen  # noqa: F401  (the fixture, re-registered here)
