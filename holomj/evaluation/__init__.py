"""Scene evaluation: measure a scene folder from its geometry (``holomj eval``, and the
prompt-fidelity benchmark's scorer ``scripts/eval/score.py``).

Independent of the planner: nothing here imports :mod:`holomj.plan` or :mod:`holomj.layout`;
names are matched through the evaluator's own vocabulary, not the planner's parser. It reads a
folder (never writes one) and takes what needs the simulator (the penetration audit, a fresh
validation) as data from the job (:mod:`holomj.jobs.eval`).

- :mod:`~holomj.evaluation.folder`: reading a folder; :mod:`~holomj.evaluation.objects`: rooms,
  openings, objects with footprints; :mod:`~holomj.evaluation.geometry`: plane helpers
- :mod:`~holomj.evaluation.vocabulary`, :mod:`~holomj.evaluation.text`: names and words
- :mod:`~holomj.evaluation.fidelity`: counts, absent, defining furniture against an annotation;
  :mod:`~holomj.evaluation.attributes`: colour, material, shape;
  :mod:`~holomj.evaluation.relations`: spatial relations;
  :mod:`~holomj.evaluation.specs`: annotations; :mod:`~holomj.evaluation.plan_spec`: a plan as one
- :mod:`~holomj.evaluation.reachability`: free floor reachable by a round robot;
  :mod:`~holomj.evaluation.access`: furniture fronts; :mod:`~holomj.evaluation.openings`: doors
  and windows kept clear; :mod:`~holomj.evaluation.support`: what rests on what, plausibly;
  :mod:`~holomj.evaluation.outside`: objects outside their room;
  :mod:`~holomj.evaluation.collisions`, :mod:`~holomj.evaluation.stability`: the audit's pairs
  and the validation report
- :mod:`~holomj.evaluation.report`: all of it as one report with a ``scores`` summary
"""
