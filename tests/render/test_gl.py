"""The OpenGL backend: EGL first, OSMesa as the fallback, one clear error when neither works."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import mujoco
import pytest

import holomj.render.folder as folder_module
from holomj.errors import HolomjError
from holomj.render import gl, render_folder


def test_open_renderer_reports_and_remembers_a_broken_backend(monkeypatch) -> None:
    monkeypatch.setattr(gl, "_failures", {})
    calls = []

    def broken(*args, **kwargs):
        calls.append(1)
        raise RuntimeError("eglInitialize failed")

    monkeypatch.setattr(mujoco, "Renderer", broken)
    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    for _ in range(2):
        with pytest.raises(gl.GLUnavailable, match="eglInitialize failed") as info:
            gl.open_renderer(model, 32, 24)
        assert f"MUJOCO_GL={gl.current_backend()}" in str(info.value)
    assert len(calls) == 1  # tried once per process


def test_the_backend_is_the_one_mujoco_bound_at_import(monkeypatch) -> None:
    """``import mujoco`` before ``import holomj`` binds GLFW, whatever MUJOCO_GL says later."""

    class GlfwContext:
        pass

    GlfwContext.__module__ = "mujoco.glfw"
    monkeypatch.setattr(mujoco, "GLContext", GlfwContext)
    monkeypatch.setenv("MUJOCO_GL", "egl")
    assert gl.current_backend() == "glfw"
    assert gl.fallback_backends() == ["egl", "osmesa"]


def test_fallbacks_skip_the_backend_that_failed(monkeypatch) -> None:
    monkeypatch.setattr(gl, "current_backend", lambda: "egl")
    assert gl.fallback_backends() == ["osmesa"]
    monkeypatch.setattr(gl, "current_backend", lambda: "osmesa")
    assert gl.fallback_backends() == ["egl"]
    env = gl.child_environment("osmesa")
    assert env["MUJOCO_GL"] == env["PYOPENGL_PLATFORM"] == "osmesa"


def test_no_working_backend_is_one_line_naming_mujoco_gl(two_room_folder: Path, monkeypatch):
    monkeypatch.setattr(gl, "_failures", {})
    monkeypatch.setattr(gl, "current_backend", lambda: "egl")

    def no_context(*args, **kwargs):
        raise gl.GLUnavailable("EGL: no display", where="MUJOCO_GL=egl")

    tried = []

    def child(backend, *args):
        tried.append(backend)
        return None, "libOSMesa.so.8: cannot open shared object file"

    monkeypatch.setattr(gl, "open_renderer", no_context)
    monkeypatch.setattr(folder_module, "_render_in_child", child)
    with pytest.raises(HolomjError) as info:
        render_folder(two_room_folder, views="top", width=32, height=24)
    message = str(info.value)
    assert tried == ["osmesa"]
    assert info.value.exit_code == 1 and "\n" not in message
    assert "MUJOCO_GL=egl: EGL: no display" in message
    assert "MUJOCO_GL=osmesa: libOSMesa.so.8" in message
    assert "set MUJOCO_GL" in message and "libosmesa6" in message
    assert not (two_room_folder / "renders").exists()


@pytest.mark.slow
def test_broken_egl_falls_back_to_osmesa_in_a_child_process(two_room_folder: Path) -> None:
    """MUJOCO_EGL_DEVICE_ID beyond the devices makes EGL fail the way a missing driver does."""
    env = {**os.environ, "MUJOCO_GL": "egl", "MUJOCO_EGL_DEVICE_ID": "99"}
    env.pop("PYOPENGL_PLATFORM", None)
    args = ["render", str(two_room_folder), "--views", "top", "--width", "32", "--height", "24"]
    proc = subprocess.run(
        [sys.executable, "-m", "holomj", *args, "--no-report", "--no-shadows", "--json"],
        capture_output=True,
        text=True,
        env=env,
        check=False,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert summary["backend"] == "osmesa"
    assert (two_room_folder / "renders" / "top.png").is_file()
    manifest = json.loads((two_room_folder / "renders" / "manifest.json").read_text())
    assert manifest["backend"] == "osmesa"
