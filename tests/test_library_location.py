"""Where the default library lives."""

from __future__ import annotations

from pathlib import Path

from holomj.library.location import default_library_root, holomj_home


def test_holomj_home_wins(monkeypatch, tmp_path: Path) -> None:
    monkeypatch.setenv("HOLOMJ_HOME", str(tmp_path / "h"))
    assert default_library_root() == tmp_path / "h" / "library"


def test_user_cache_otherwise(monkeypatch, tmp_path: Path) -> None:
    monkeypatch.delenv("HOLOMJ_HOME", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    assert holomj_home() == tmp_path / "cache" / "holomj"
    monkeypatch.delenv("XDG_CACHE_HOME")
    assert holomj_home() == Path.home() / ".cache" / "holomj"
