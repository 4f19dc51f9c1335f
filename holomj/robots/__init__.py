"""Robots in scenes: which robots exist, preparing their MJCF, where they stand, attaching them.

- :mod:`registry`: ``panda`` / ``jaco`` / an MJCF path -> :class:`RobotSource`
- :mod:`prepare`: fixed base, home pose as ``qpos0``, files embedded, footprint
- :mod:`occupancy`, :mod:`reach`, :mod:`placement`: floor grid, reachability, the spot
- :mod:`attach`: put it into a compiled scene; put a recorded robot back on a recompile
  (``holomj add-robot`` is the job :mod:`holomj.jobs.add_robot`)
"""

from holomj.robots.attach import add_robot, attach_recorded, reattach_robot
from holomj.robots.placement import Spot, choose_spot
from holomj.robots.prepare import PreparedRobot, prepare_robot
from holomj.robots.registry import RobotSource, available_robots, resolve_robot
from holomj.spec.robot import Footprint, RobotRecord

__all__ = [
    "Footprint",
    "PreparedRobot",
    "RobotRecord",
    "RobotSource",
    "Spot",
    "add_robot",
    "attach_recorded",
    "available_robots",
    "choose_spot",
    "prepare_robot",
    "reattach_robot",
    "resolve_robot",
]
