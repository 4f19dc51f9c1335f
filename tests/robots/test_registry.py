"""Robot specs: registry names, MJCF paths, and errors that list what is available."""

from __future__ import annotations

from pathlib import Path

import pytest

from holomj.errors import InputError
from holomj.robots import registry
from holomj.robots.registry import available_robots, installed_robots, resolve_robot


def test_jaco_resolves_to_dm_control_files() -> None:
    source = resolve_robot("jaco")
    assert source.xml.name == "jaco_arm.xml" and source.xml.is_file()
    assert source.hand is not None and source.hand.xml.name == "jaco_hand.xml"
    assert source.package == "dm-control"
    assert set(source.home) == {f"joint_{i}" for i in range(1, 7)}


def test_available_robots_names_every_registry_entry() -> None:
    notes = available_robots()
    assert set(notes) == {"panda", "jaco"}
    assert "jaco" in installed_robots()
    for name in notes:
        if name not in installed_robots():
            assert notes[name].startswith("not installed: pip install")


def test_unknown_name_lists_the_available_robots() -> None:
    with pytest.raises(InputError) as info:
        resolve_robot("r2d2")
    message = info.value.one_line()
    assert "unknown robot 'r2d2'" in message and "jaco" in message and "panda" in message
    assert info.value.exit_code == 2


def test_missing_mjcf_file(tmp_path: Path) -> None:
    with pytest.raises(InputError, match=r"robot MJCF file not found.*jaco"):
        resolve_robot(str(tmp_path / "nope.xml"))


def test_mjcf_path_resolves(tmp_path: Path) -> None:
    xml = tmp_path / "arm.xml"
    xml.write_text("<mujoco/>")
    source = resolve_robot(str(xml))
    assert source.xml == xml.resolve() and source.name == "arm" and source.package is None


def test_uninstalled_package_names_the_pip_command(monkeypatch: pytest.MonkeyPatch) -> None:
    original = registry._package_file

    def without_panda(distribution: str, relative: str) -> Path | None:
        return None if distribution == "dm-robotics-panda" else original(distribution, relative)

    monkeypatch.setattr(registry, "_package_file", without_panda)
    assert "panda" not in installed_robots()
    assert available_robots()["panda"] == f"not installed: {registry.PANDA_PIP}"
    with pytest.raises(InputError) as info:
        resolve_robot("panda")
    message = info.value.one_line()
    assert "pip install dm-robotics-panda --no-deps" in message and "jaco" in message
