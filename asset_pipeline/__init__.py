"""Offline asset processing for holomj: mesh import (CoACD), thumbnails, the library writer and
the procedural default library.

This package imports :mod:`holomj` (its errors and spec); holomj imports it only lazily, inside
its jobs (the default library, asset imports, synthesis on demand). Neither import chooses a GL
backend: ``import holomj`` sets nothing, and it is :mod:`holomj.jobs` (imported when a job runs)
that sets ``MUJOCO_GL`` to ``egl`` unless it is set already. Code that renders thumbnails
through this package without running a holomj job sets ``MUJOCO_GL`` itself (``egl`` or
``osmesa`` on a machine without a display) before MuJoCo is first imported.
"""
