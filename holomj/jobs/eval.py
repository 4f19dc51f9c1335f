"""The eval job (``holomj eval``): measure a scene folder from its geometry.

Against what: an annotation (``spec``: a dict, or a .json/.jsonl file in the format of
``scripts/eval/prompts_dev.jsonl``); else the folder's own ``plan.json``; else, with a
``prompt``, the offline planner's plan of it (the one place evaluation uses the planner: only
for the list of requested objects and relations); else nothing (counts, attributes and
relations are then not measured). The metrics are :mod:`holomj.evaluation`'s; this job adds
what needs the simulator: the penetration audit of the folder's ``scene.xml`` at t = 0 and,
with ``validate=True`` when the folder has no ``report.json``, a fresh validation (kept in
memory; the folder is never written).
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

from holomj.errors import InputError
from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.plan_spec import spec_from_plan
from holomj.evaluation.report import EvalReport, evaluate_scene
from holomj.evaluation.specs import check_spec, read_spec
from holomj.evaluation.vocabulary import Vocabulary
from holomj.file_names import PLAN_JSON, REPORT_JSON, SCENE_XML
from holomj.jobs.folder import read_json_report, read_scene, require_scene_folder

if TYPE_CHECKING:
    from holomj.spec.plan import ScenePlan
    from holomj.spec.report import PenetrationPair
    from holomj.spec.scene import SceneSpec

AUDIT_TOLERANCE_M = 0.001

__all__ = ["EvalReport", "audit_scene_xml", "evaluate", "read_plan"]


def evaluate(
    folder: Path | str,
    *,
    prompt: str | None = None,
    spec: Path | str | dict[str, Any] | None = None,
    spec_id: str | None = None,
    validate: bool = False,
    seed: int = 0,
) -> EvalReport:
    """Measure the scene folder ``folder`` (see :mod:`holomj.evaluation.report` for the metrics).

    ``spec``: an annotation (dict) or a .json/.jsonl file of them (``spec_id`` picks one);
    ``prompt``: what the scene was asked to be, planned offline with ``seed`` when the folder
    has no plan.json; ``validate``: run the validation when the folder has no report.json.

    Raises :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, both a
    prompt and a spec, or a bad spec (naming the field), and
    :class:`~holomj.errors.FormatError` for unreadable files of the folder (a scene.xml
    MuJoCo cannot load, a broken plan.json).
    """
    start = time.perf_counter()
    folder = require_scene_folder(Path(folder), "holomj generate' or 'holomj compile")
    if prompt is not None and spec is not None:
        raise InputError("give --prompt or --spec, not both", where="holomj eval")
    if prompt is not None and not prompt.strip():
        raise InputError("empty prompt", where="--prompt")
    vocab = Vocabulary.load()
    timings: dict[str, float] = {}
    target, against, notes = _target(folder, prompt, spec, spec_id, seed, vocab)
    timings["plan"] = round(time.perf_counter() - start, 3)

    clock = time.perf_counter()
    scene_spec = read_scene(folder)
    penetrations = audit_scene_xml(folder, scene_spec)
    timings["audit"] = round(time.perf_counter() - clock, 3)

    clock = time.perf_counter()
    report = read_json_report(folder, REPORT_JSON)
    source = REPORT_JSON
    if report is None and validate:
        from holomj.jobs.validate import validate as run_validation

        report = run_validation(folder).model_dump(mode="json")
        source = "validated by eval (furniture free)"
    timings["validate"] = round(time.perf_counter() - clock, 3)

    clock = time.perf_counter()
    result = evaluate_scene(
        MeasuredFolder(folder),
        target,
        vocab=vocab,
        against=against,
        penetrations=penetrations,
        stability_report=report,
        stability_source=source,
        notes=notes,
    )
    result.timings = {
        **timings,
        **result.timings,
        "measure": round(time.perf_counter() - clock, 3),
        "total": round(time.perf_counter() - start, 3),
    }
    return result


def _target(
    folder: Path,
    prompt: str | None,
    spec: Path | str | dict[str, Any] | None,
    spec_id: str | None,
    seed: int,
    vocab: Vocabulary,
) -> tuple[dict[str, Any] | None, dict[str, Any], list[str]]:
    """(the annotation to measure against, what it came from, notes)."""
    if isinstance(spec, dict):
        target = check_spec(spec, "spec")
        return target, {"source": "spec", "id": target.get("id")}, []
    if spec is not None:
        target = read_spec(spec, spec_id)
        return target, {"source": "spec", "file": str(spec), "id": target.get("id")}, []
    plan = read_plan(folder)
    if plan is not None:
        notes = []
        if prompt is not None and " ".join(prompt.split()) != " ".join(plan.prompt.split()):
            notes.append(
                "--prompt differs from the prompt of the folder's plan.json; measured "
                "against plan.json"
            )
        against: dict[str, Any] = {
            "source": PLAN_JSON,
            "prompt": plan.prompt,
            "planner": plan.planner,
        }
        return spec_from_plan(plan, vocab, own=True), against, notes
    if prompt is not None:
        from holomj.jobs.plan import PlanOptions, plan_scene

        plan = plan_scene(prompt, PlanOptions(seed=seed, planner="offline"))
        against = {"source": "prompt", "prompt": prompt, "planner": "offline", "seed": seed}
        note = "no plan.json: the prompt was planned offline, objects matched by category"
        return spec_from_plan(plan, vocab, own=False), against, [note]
    note = "no plan.json, --prompt or --spec: counts, attributes and relations not measured"
    return None, {"source": None}, [note]


def read_plan(folder: Path) -> ScenePlan | None:
    """The folder's ``plan.json`` (None when absent); a one-line error when it is broken."""
    from holomj.spec.base import validate_model
    from holomj.spec.plan import ScenePlan

    data = read_json_report(folder, PLAN_JSON)
    if data is None:
        return None
    return validate_model(ScenePlan, data, str(folder / PLAN_JSON))


def audit_scene_xml(folder: Path, scene: SceneSpec) -> list[PenetrationPair]:
    """The penetration audit of the folder's ``scene.xml`` as written, at its initial pose:
    pairs of colliders (objects, floor, structure) deeper than 1 mm."""
    from holomj.mjcf import names
    from holomj.mjcf.loading import load_model_file
    from holomj.physics.audit import audit
    from holomj.physics.scene_io import LoadedScene

    path = folder / SCENE_XML
    model = load_model_file(path)
    objects = {}
    for obj in scene.objects:
        try:
            objects[obj.id] = model.body(names.object_body(obj.id)).id
        except KeyError:  # not in the model (a foreign edit of scene.xml): not audited by name
            continue
    loaded = LoadedScene(path, model, objects, scene=scene)
    return audit(loaded, tolerance=AUDIT_TOLERANCE_M).penetrations
