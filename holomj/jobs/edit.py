"""The edit job (``holomj edit OUT OPS.json [-o NEW]``): apply edit operations to a scene folder.

The operations (:mod:`holomj.spec.edit`) are read and checked first: a file that is not valid
JSON or not a valid list of operations raises :class:`~holomj.errors.InputError` (the command
line exits 2) before anything is touched. They are then applied in memory
(:mod:`holomj.edit.apply`): the scene's own assets come from its ``assets/`` library, new ones
from ``library_path`` (the default library when the CLI is used; assets it lacks are made on
demand, as ``generate`` makes them). The edited scene is compiled (with the folder's robot),
validated like ``holomj validate OUT`` does (furniture free), and written atomically, into
``out`` (a new folder) or back into ``folder``: ``scene.xml``, ``scene.json``, ``assets/``,
``objects.json``, the navigation map afresh, ``report.json`` (the new validation) and
``edit_report.json`` (:class:`~holomj.spec.edit.EditReport`: every operation applied or refused
with the reason, what was added, removed and moved, the validation summary). Everything else
of the folder is kept; renders and ``report.html`` then show the scene before the edit
(``stale_files``).

:func:`apply_edits` is what ``holomj refine`` calls on a copy of a scene: it returns the report
and writes the edited scene to ``out``.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from holomj.errors import InputError
from holomj.file_names import RENDERS_DIR, REPORT_HTML, REPORT_JSON
from holomj.jobs.folder import (
    attach_folder_robot,
    open_library,
    prepare_output,
    read_robot,
    read_scene,
    require_scene_folder,
    write_scene_folder,
)
from holomj.library.store import AssetLibrary
from holomj.seeds import MAX_SEED
from holomj.spec.base import read_json
from holomj.spec.edit import EditReport, parse_operations
from holomj.spec.report import StabilityReport, Thresholds

EDIT_REPORT = "edit_report.json"


def read_operations(path: Path | str) -> list[Any]:
    """The operations of a JSON file; :class:`~holomj.errors.InputError` (naming the file and
    the field) when it is unreadable or not a valid operations list."""
    path = Path(path)
    return parse_operations(read_json(path), str(path))


def load_operations(ops: Path | str | Sequence[Any]) -> list[Any]:
    """Operations from a file path, or from a list of operation models or plain dicts."""
    if isinstance(ops, (str, Path)):
        return read_operations(ops)
    if isinstance(ops, dict) or not isinstance(ops, Sequence):
        return parse_operations(ops, "operations")
    data = [op.model_dump(mode="json") if hasattr(op, "model_dump") else op for op in ops]
    return parse_operations(data, "operations")


def apply_edits(
    folder: Path | str,
    ops: Path | str | Sequence[Any],
    out: Path | str | None = None,
    *,
    seed: int = 0,
    library_path: Path | None = None,
    overwrite: bool = False,
    validate: bool = True,
    text_model: Path | None = None,
    materials: Path | None = None,
    log: Callable[[str], None] | None = None,
) -> EditReport:
    """Apply ``ops`` (a file, or a list of operations) to the scene in ``folder`` and write the
    result to ``out`` (default: ``folder`` itself); see the module docstring.

    Raises :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, a bad
    operations list or seed, and :class:`~holomj.errors.OutputExistsError` when ``out`` is
    another folder that exists (without ``overwrite``). Refused operations are not errors: they
    are in the report (``.refused``, ``.operations[i].reason``).
    """
    start = time.perf_counter()
    folder = require_scene_folder(Path(folder), "holomj generate' or 'holomj compile")
    operations = load_operations(ops)
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"must lie in [0, {MAX_SEED}]", where="--seed")
    target = Path(out) if out is not None else folder
    in_place = target.resolve() == folder.resolve()
    if not in_place:
        prepare_output(target, overwrite)
    from holomj.edit.apply import apply_operations
    from holomj.edit.state import EditContext

    scene = read_scene(folder)
    source = AssetLibrary.open(library_path) if library_path is not None else None
    synthesiser = None
    if source is not None:
        from holomj.jobs.synthesis import LibrarySynthesiser

        synthesiser = LibrarySynthesiser(source)
    ctx = EditContext(
        own=open_library(folder),
        source=source,
        synthesiser=synthesiser,
        seed=seed,
        attach=lambda compiled: attach_folder_robot(compiled, folder),
        text_model=text_model,
        materials=materials,
        blockers=_robot_blockers(folder),
    )
    applied = apply_operations(scene, operations, ctx, log=log)
    from holomj.mjcf.compiler import compile_scene

    library = ctx.library
    compiled = attach_folder_robot(compile_scene(applied.scene, library), folder)
    written: dict[str, Any] = {}
    summary = None
    if validate:
        report = _validate(applied.scene, library, folder)
        written[REPORT_JSON] = report.model_dump(mode="json")
        summary = validation_summary(report)
    stale = [name for name in (RENDERS_DIR, REPORT_HTML) if (folder / name).exists()]
    result = EditReport(
        source=str(folder),
        output=str(target),
        seed=seed,
        operations=applied.results,
        applied=applied.applied,
        refused=applied.refused,
        added=applied.added,
        removed=applied.removed,
        moved=applied.moved,
        validation=summary,
        written=True,
        stale_files=stale,
    )
    result.seconds = round(time.perf_counter() - start, 3)
    written[EDIT_REPORT] = result.model_dump(mode="json")
    write_scene_folder(compiled, target, overwrite=True, extra_json=written, keep_from=folder)
    return result


def validation_summary(report: StabilityReport) -> dict[str, Any]:
    """What an edit report says of a validation: ok, counts, the deepest penetration, and every
    object that is not stable with its reasons."""
    return {
        "ok": report.ok,
        "furniture": report.furniture,
        "counts": report.counts,
        "max_penetration_m": report.max_penetration_m,
        "unstable": {obj.name: list(obj.reasons) for obj in report.unstable()},
    }


def _validate(scene: Any, library: AssetLibrary, folder: Path) -> StabilityReport:
    """The validation ``holomj validate FOLDER`` makes of ``scene`` (with the folder's robot):
    default thresholds, furniture free, no sleeping."""
    from holomj.mjcf.compiler import compile_scene
    from holomj.physics.scene_io import loaded_from_compiled
    from holomj.physics.settle import validate_loaded

    compiled = attach_folder_robot(compile_scene(scene, library, furniture="free"), folder)
    loaded = loaded_from_compiled(compiled, library, folder, folder)
    return validate_loaded(loaded, Thresholds(), "free", sleep=False)


def _robot_blockers(folder: Path) -> tuple[Any, ...]:
    """The folder's robot (if any) as a disc new furniture keeps clear of."""
    robot = read_robot(folder)
    if robot is None:
        return ()
    from shapely.geometry import Point

    from holomj.edit.floor import Blocker

    base = Point(robot.position[0], robot.position[1]).buffer(robot.footprint.radius_m)
    return (Blocker("robot", base, robot.footprint.height_m, robot.room),)
