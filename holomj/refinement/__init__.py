"""Refinement: what ``holomj refine`` and ``holomj populate --instruction`` decide, in memory.

The jobs layer (:mod:`holomj.jobs.refine`, :mod:`holomj.jobs.pointing`) reads and writes
folders, renders, applies edits and measures; this package turns what it measured into the
next edit operations, and never touches a folder:

- :mod:`~holomj.refinement.summary`: the scene as the planners see it (ids, categories, rooms,
  positions, sizes, windows and doors);
- :mod:`~holomj.refinement.instruction`: an instruction ("add a reading corner with an armchair and
  a floor lamp by the window") read with the offline planner's prompt parser into items to add,
  remove or move, with rooms and relations;
- :mod:`~holomj.refinement.goals`: those items as an annotation the evaluator measures, and the
  refine score;
- :mod:`~holomj.refinement.offline`: the offline planner (edits that fix what the evaluation finds);
- :mod:`~holomj.refinement.safety`: every reply of a model checked as data (JSON against the
  operations schema, known ids, sane sizes and positions, a bounded number of operations, no
  code); nothing returned is ever executed;
- :mod:`~holomj.refinement.llm`: the vision-language planner over an OpenAI-compatible endpoint
  (rendered views as image parts, a text-only fallback), with token, image and time accounting;
- :mod:`~holomj.refinement.pointing`: pixels to rays onto a receptacle's surface, and the
  conversation that names the next small object and points at where it goes.
"""
