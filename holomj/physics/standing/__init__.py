"""Make an imported house stand (``holomj compile``'s default for ProcTHOR/Holodeck houses and
SceneDefs): see :mod:`holomj.physics.standing.stage`."""

from holomj.physics.standing.stage import StandOptions, StandOutcome, make_stand

__all__ = ["StandOptions", "StandOutcome", "make_stand"]
