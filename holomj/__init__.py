"""holomj: physically valid indoor scenes for MuJoCo.

Rendering needs an OpenGL backend chosen before MuJoCo (or dm_control) is imported; holomj
defaults to headless EGL unless ``MUJOCO_GL`` is already set.
"""

import os

os.environ.setdefault("MUJOCO_GL", "egl")

__version__ = "0.1.0"
