"""The jobs layer: one module per user-facing job, and the one module that owns output folders.

- :mod:`~holomj.jobs.folder`: the output folder's file names; reading and writing it atomically
- :mod:`~holomj.jobs.compile`, :mod:`~holomj.jobs.generate`, :mod:`~holomj.jobs.validate`,
  :mod:`~holomj.jobs.populate`, :mod:`~holomj.jobs.add_robot`, :mod:`~holomj.jobs.info`:
  the jobs the CLI and the Python API (``holomj.generate(...)`` and friends) run
- :mod:`~holomj.jobs.plan` (a prompt's plan; the planner names),
  :mod:`~holomj.jobs.assets` (asset libraries: build, import, list, show, remove),
  :mod:`~holomj.jobs.materials`, :mod:`~holomj.jobs.layout_solve` (one room's layout from a
  problem file), :mod:`~holomj.jobs.schema`: the other commands' jobs
- :mod:`~holomj.jobs.arena`: a scene folder as a dm_control composer Arena

Below this layer, stages take and return data in memory and never touch an output folder.
"""

import os

# Jobs may render: MuJoCo binds its OpenGL backend when it is first imported, so choose headless
# EGL now, unless the user chose one (``import holomj`` alone sets nothing; running a job does).
os.environ.setdefault("MUJOCO_GL", "egl")
