"""The OpenGL backend: EGL first, OSMesa as the fallback, one clear error when neither works.

The fallback to a child process is the render job's (tests/jobs/test_render.py)."""

from __future__ import annotations

import mujoco
import pytest

from holomj.rendering import gl


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
