"""The validate job: audit a scene at t = 0, settle it, judge every object (and ``--repair``).

``validate(path)`` takes a holomj output folder (recompiled from its ``scene.json``, so furniture
can be simulated free, with its robot) or any MJCF file (its free bodies are the objects). With
``repair=True`` the folder is repaired first (:mod:`holomj.physics.repair`) and written back
atomically, keeping every other file, then validated again.
"""

from __future__ import annotations

from pathlib import Path

from holomj.errors import InputError
from holomj.jobs.folder import (
    attach_folder_robot,
    load_for_physics,
    open_library,
    prepare_output,
    scene_folder,
    write_scene_folder,
)
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.mjcf.objects import Furniture
from holomj.physics.repair import RepairOutcome, repair_scene
from holomj.physics.settle import validate_loaded
from holomj.spec.choices import one_of
from holomj.spec.report import StabilityReport, Thresholds
from holomj.spec.scene import SceneSpec

FURNITURE_MODES: tuple[Furniture, ...] = ("free", "static", "as-is")


def validate(
    path: Path | str,
    *,
    thresholds: Thresholds | None = None,
    furniture: str = "free",
    sleep: bool = False,
    repair: bool = False,
) -> StabilityReport:
    """Validate the scene at ``path`` (a holomj folder, its scene.xml, or any MJCF file).

    With ``repair``, the folder is repaired and rewritten first; the report then lists what was
    moved (``repaired``) and what could not be saved (``unsaved``).

    Raises :class:`~holomj.errors.InputError` for a bad option or a ``repair`` of something
    that is not a holomj folder, :class:`~holomj.errors.FormatError` when the scene cannot be
    read or loaded.
    """
    mode = one_of(furniture, FURNITURE_MODES)
    if mode is None:
        raise InputError(
            f"unknown value {furniture!r}", where="--furniture", fix="use free, static or as-is"
        )
    if repair:
        outcome = repair_folder(path, thresholds, mode, sleep)
        report = validate(outcome_folder(path), thresholds=thresholds, furniture=mode, sleep=sleep)
        return report.model_copy(update={"repaired": outcome.repaired, "unsaved": outcome.unsaved})
    loaded = load_for_physics(Path(path), furniture=mode)
    return validate_loaded(loaded, thresholds, mode, sleep)


def outcome_folder(path: Path | str) -> Path:
    """The holomj folder ``path`` names (itself or the folder of its scene.xml)."""
    folder = scene_folder(Path(path))
    if folder is None:
        raise InputError(
            "--repair needs a holomj scene folder (scene.json and assets/)",
            where=str(path),
            fix="validate without --repair, or compile the scene with 'holomj compile'",
        )
    return folder


def repair_folder(
    path: Path | str,
    thresholds: Thresholds | None = None,
    furniture: Furniture = "free",
    sleep: bool = False,
) -> RepairOutcome:
    """Repair the holomj folder at ``path`` and write it back atomically (other files kept)."""
    folder = outcome_folder(path)
    prepared = prepare_output(folder, overwrite=True)  # rewritable, before any work
    library = open_library(folder)
    loaded = load_for_physics(folder, furniture=furniture, library=library)

    def recompile(scene: SceneSpec, mode: Furniture) -> CompiledScene:
        return attach_folder_robot(compile_scene(scene, library, furniture=mode), folder)

    outcome = repair_scene(loaded, recompile, thresholds, furniture, sleep)
    write_scene_folder(outcome.compiled, prepared, keep_from=folder)
    return outcome
