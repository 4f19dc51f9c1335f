"""Scene edits applied in memory: one module per operation family, :mod:`holomj.edit.apply`
runs a list of them.

The operations are data (:mod:`holomj.spec.edit`). Each one is applied to the scene or refused
with a reason, and only what it touches changes: a new floor object is laid out among the
others held where they are (:mod:`holomj.edit.floor`), small objects are dropped with the
simulator (:func:`holomj.physics.spawn.populate`), small objects on a moved receptacle move
along, those on a removed one go with it. Folders are read and written by the jobs layer
(:mod:`holomj.jobs.edit`), which also validates the result.
"""
