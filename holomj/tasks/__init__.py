"""Robot tasks on generated scenes: success predicates on MuJoCo state and task proposals.

- :mod:`holomj.tasks.predicates`: a task's success as a condition on ``MjModel``/``MjData`` and
  the scene's ``objects.json`` record, held for the task's ``hold_s``;
- :mod:`holomj.tasks.propose`: feasible tasks from ``objects.json`` and ``navmap.json``;
- :mod:`holomj.tasks.scene_objects`: lookups into ``objects.json`` with errors that list ids.

The tasks themselves are data: :mod:`holomj.spec.tasks`.
"""
