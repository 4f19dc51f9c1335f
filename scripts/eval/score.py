"""Prompt-fidelity scorer for holomj scene folders (issue 14), independent of the planner.

A thin command line over :mod:`holomj.evaluation` (the same measurements as ``holomj eval``):
it reads only the scene folder (``scene.json``, ``objects.json``, ``assets/*/asset.json`` and
their OBJ meshes, ``report.json``, ``navmap.json``) and one hand-written annotation (a line of
``scripts/eval/prompts_dev.jsonl``). It imports nothing of holomj but ``holomj.evaluation``,
which never imports the planner (``holomj.plan``) or the layout: names are matched to scene
objects through the evaluator's own vocabulary (``holomj/data/evaluation/vocabulary.json``),
not through the planner's parser. ::

    python scripts/eval/score.py FOLDER --spec scripts/eval/prompts_dev.jsonl --id m001
    python scripts/eval/score.py FOLDER --spec '{"id": "x", "prompt": "...", "objects": [...]}'

Methods and thresholds are documented where they are implemented:

- names, counts, absent things, defining furniture, validation: ``holomj/evaluation/fidelity.py``
- colour, material, shape: ``holomj/evaluation/attributes.py``
- relations (near 1.5 m, next to 0.5 m, facing 30 degrees, against wall 15 cm, ...):
  ``holomj/evaluation/relations.py``
- doors clear (1 m deep zone, 25 cm2 overlap): ``holomj/evaluation/openings.py``
- reachability of a 0.2 m robot from the entrance (navmap.json, else a 5 cm raster):
  ``holomj/evaluation/reachability.py``

The record printed is the fidelity benchmark's (``scripts/bench_fidelity.py``): id, prompt,
summary ``[held, total]`` per kind, validation, doors_clear, reachability, and every verdict.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from shapely.geometry import box

from holomj.evaluation.attributes import (
    object_colours,
    object_has_shape,
    object_materials,
    rgba_colour,
)
from holomj.evaluation.fidelity import Scorer, score_folder
from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.objects import EvaluatedObject, EvaluatedRoom, Opening
from holomj.evaluation.reachability import reachability
from holomj.evaluation.relations import RELATIONS, Verdict
from holomj.evaluation.specs import load_specs
from holomj.evaluation.text import normalise, singular_forms, slug
from holomj.evaluation.vocabulary import Vocabulary, default_vocabulary_file

VOCABULARY_FILE = default_vocabulary_file()

__all__ = [
    "RELATIONS",
    "VOCABULARY_FILE",
    "EvaluatedObject",
    "EvaluatedRoom",
    "MeasuredFolder",
    "Opening",
    "Scorer",
    "Verdict",
    "Vocabulary",
    "box",
    "load_specs",
    "main",
    "normalise",
    "object_colours",
    "object_has_shape",
    "object_materials",
    "reachability",
    "rgba_colour",
    "score_folder",
    "singular_forms",
    "slug",
]


def main(argv: list[str] | None = None) -> int:
    """CLI: print the JSON record of one folder."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--spec", required=True, help="A JSON line, or a .jsonl/.json file.")
    parser.add_argument("--id", help="Which annotation of the file (by its id).")
    parser.add_argument("--vocabulary", type=Path, default=VOCABULARY_FILE)
    args = parser.parse_args(argv)
    specs = load_specs(args.spec)
    if args.id:
        specs = [s for s in specs if s.get("id") == args.id]
    if len(specs) != 1:
        print(f"--spec gives {len(specs)} annotations; pick one with --id", file=sys.stderr)
        return 2
    if not (args.folder / "scene.json").is_file():
        print(f"{args.folder}: no scene.json", file=sys.stderr)
        return 2
    record = score_folder(args.folder, specs[0], Vocabulary.load(args.vocabulary))
    print(json.dumps(record, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
