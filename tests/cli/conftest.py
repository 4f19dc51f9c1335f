"""Fixtures of the command-line tests: the compiled two-room folder of the render tests."""

from tests.rendering.conftest import compiled_two_room, two_room_folder

__all__ = ["compiled_two_room", "two_room_folder"]
