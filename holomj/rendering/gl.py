"""Which OpenGL backend renders: EGL (GPU driver or Mesa on the CPU), OSMesa as the fallback.

MuJoCo binds its GL backend once per process, when it is imported, from ``MUJOCO_GL`` (holomj
defaults it to ``egl``), and PyOpenGL binds its platform at the same moment. So a process whose
backend cannot make a context cannot switch to another one: :func:`open_renderer` reports that
as :class:`GLUnavailable`, and the caller re-runs the job in a child process with the next
backend (:func:`fallback_backends`). When no backend works, :func:`no_backend_error` says so in
one line that names ``MUJOCO_GL``.
"""

from __future__ import annotations

import os

import mujoco

from holomj.errors import HolomjError

BACKENDS = ("egl", "osmesa")
_failures: dict[str, str] = {}  # backend -> why it failed in this process (tried once)


class GLUnavailable(HolomjError):
    """This process cannot create an OpenGL context with its backend."""


def current_backend() -> str:
    """The backend MuJoCo was imported with in this process: egl, osmesa, glfw, ...

    Read from the GL context class MuJoCo bound at import, not from ``MUJOCO_GL`` now, which
    may have been set after ``mujoco`` was imported.
    """
    context = getattr(mujoco, "GLContext", None)
    module = getattr(context, "__module__", "") or ""
    if module.startswith("mujoco."):
        return module.split(".")[1]
    return os.environ.get("MUJOCO_GL", "").strip().lower() or "glfw"


def open_renderer(model: mujoco.MjModel, width: int, height: int) -> mujoco.Renderer:
    """A ``mujoco.Renderer`` for ``model``; :class:`GLUnavailable` when no context can be made."""
    backend = current_backend()
    if backend in _failures:
        raise GLUnavailable(_failures[backend], where=f"MUJOCO_GL={backend}")
    if getattr(mujoco, "GLContext", None) is None:
        why = "MuJoCo could not load this OpenGL backend"
        _failures[backend] = why
        raise GLUnavailable(why, where=f"MUJOCO_GL={backend}")
    try:
        return mujoco.Renderer(model, height=height, width=width)
    except ValueError:
        raise  # a size beyond the framebuffer: our bug, not the backend's
    except Exception as err:  # GL errors come as RuntimeError, ImportError, OSError, ...
        why = f"{type(err).__name__}: {' '.join(str(err).split()) or 'no message'}"
        _failures[backend] = why
        raise GLUnavailable(why, where=f"MUJOCO_GL={backend}") from None


def renderer_name() -> str:
    """The OpenGL renderer of the current context (e.g. ``llvmpipe`` for Mesa on the CPU)."""
    try:
        from OpenGL import GL

        name = GL.glGetString(GL.GL_RENDERER)
    except Exception:  # PyOpenGL missing or no current context: the name is only informative
        return "unknown"
    return name.decode(errors="replace") if isinstance(name, bytes) else str(name)


def fallback_backends() -> list[str]:
    """Backends to try in a child process after this process's backend failed, in order."""
    return [b for b in BACKENDS if b != current_backend()]


def child_environment(backend: str) -> dict[str, str]:
    """The environment of a child process that renders with ``backend``."""
    env = dict(os.environ)
    env["MUJOCO_GL"] = backend
    env["PYOPENGL_PLATFORM"] = backend  # mujoco set it to the parent's backend on import
    return env


def no_backend_error(failures: dict[str, str]) -> HolomjError:
    """The one-line error when no backend can render, listing why each one failed."""
    tried = "; ".join(f"MUJOCO_GL={name}: {why}" for name, why in failures.items())
    return HolomjError(
        f"no OpenGL backend can render headless ({tried})",
        fix="install Mesa's EGL and OSMesa libraries (Debian: libegl1 libegl-mesa0 "
        "libgl1-mesa-dri libosmesa6) or a GPU driver, or set MUJOCO_GL to a backend that works",
    )
