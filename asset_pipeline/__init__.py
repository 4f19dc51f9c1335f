"""Offline asset processing for holomj: mesh import (CoACD), thumbnails, the library writer and
the procedural default library.

This package imports :mod:`holomj`; holomj itself never imports it (except lazily from the
CLI). Importing holomj first also picks the headless GL backend before MuJoCo loads.
"""

import holomj  # noqa: F401  (sets MUJOCO_GL before any mujoco import)
