"""Gymnasium environments on generated scenes: :func:`make` (``holomj.envs.make(folder, task,
robot=...)``) gives a :class:`~holomj.envs.arm_env.SceneArmEnv`: the attached fixed-base arm,
one task of :mod:`holomj.spec.tasks`, its success predicate as the reward."""

from holomj.envs.arm_env import SceneArmEnv
from holomj.envs.make import make

__all__ = ["SceneArmEnv", "make"]
