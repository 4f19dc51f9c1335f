"""The compose stage: a plan and its retrieved assets -> a SceneSpec.

The house shell (:mod:`~holomj.compose.house_shell`), each room furnished
(:mod:`~holomj.compose.room_furnishing`, with :mod:`~holomj.compose.room_assets`,
:mod:`~holomj.compose.layout_problem` and :mod:`~holomj.compose.wall_and_ceiling`), the plan
grown where furniture did not fit (:mod:`~holomj.compose.house`), the small objects chosen for
each receptacle (:mod:`~holomj.compose.small_objects`) and the verdicts on the plan's structural
relations (:mod:`~holomj.compose.relation_report`). Data in memory only: no folder is read or
written here, and nothing is simulated (the jobs layer drops the small objects with physics).
"""
