"""The populate job: spawn-and-drop small objects onto a receptacle of a scene folder.

The scene's own assets come from its ``assets/`` library, the new objects' from ``library_path``
(the default library when the CLI is used). The folder's robot (``robot.json``), if any, stays:
candidates are dropped with it in the world and the scene is recompiled with it. The populated
scene is written back into the same folder atomically: ``scene.xml``, ``scene.json``,
``assets/``, ``objects.json``, ``navmap.json``, ``navmap.png`` and ``robot.json`` afresh;
``report.json``, when the folder has one, replaced by the validation of the new scene (what
``holomj validate SCENE`` reports: furniture free); and ``populate_report.json`` (every placement
outcome; earlier runs are kept under ``runs``). Everything else is kept as it was; renders and
``report.html`` then show the scene before this run, which the report lists under
``stale_files`` (``holomj render SCENE`` refreshes them).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.errors import HolomjError, InputError
from holomj.jobs.folder import (
    POPULATE_REPORT,
    RENDERS_DIR,
    REPORT_HTML,
    REPORT_JSON,
    attach_folder_robot,
    open_library,
    read_json_report,
    read_scene,
    require_scene_folder,
    write_scene_folder,
)
from holomj.jobs.receptacle_priors import DEFAULT_COUNT, prior_requests
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.physics.scene_io import loaded_from_compiled
from holomj.physics.settle import validate_loaded
from holomj.physics.spawn import find_object, merge_libraries, populate
from holomj.seeds import MAX_SEED, seed_rng, stage_rng
from holomj.spec.report import StabilityReport, Thresholds
from holomj.spec.scene import SceneSpec

MAX_ATTEMPTS = 1000
MAX_DRAWN = 20  # objects drawn for a receptacle when none are named
_ITEM = re.compile(r"^\s*([A-Za-z0-9_][A-Za-z0-9_.:|+\- ]*?)\s*(?::\s*(\d+)\s*)?$")


def parse_objects(text: str) -> list[tuple[str, int]]:
    """``"mug:2, book, apple:3"`` -> ``[("mug", 2), ("book", 1), ("apple", 3)]``.

    Raises :class:`~holomj.errors.InputError` naming ``--objects`` for a bad item."""
    requests = []
    for item in text.split(","):
        if not item.strip():
            continue
        name, count = item.strip(), 1
        head, _, number = name.rpartition(":")
        if head and number.strip().isdigit():
            name, count = head, int(number)
        name = name.strip()
        if not _ITEM.match(name) or count < 1 or count > 1000:
            raise InputError(
                f"bad item {item.strip()!r}",
                where="--objects",
                fix="write CATEGORY[:COUNT],... with 1 <= COUNT <= 1000, e.g. 'mug:2,book'",
            )
        requests.append((name, count))
    if not requests:
        raise InputError("no objects requested", where="--objects", fix="e.g. 'mug:2,book'")
    return requests


@dataclass
class PopulateResult:
    """What :func:`populate_folder` did."""

    folder: str
    receptacle: str
    requested: int
    placed: int
    report: dict[str, Any]

    @property
    def all_placed(self) -> bool:
        """True when every requested object was placed."""
        return self.placed == self.requested


def populate_folder(
    folder: Path | str,
    receptacle_id: str,
    requests: list[tuple[str, int]] | str | None,
    *,
    seed: int = 0,
    library_path: Path | None = None,
    max_attempts: int = 20,
    count: int = DEFAULT_COUNT,
) -> PopulateResult:
    """Populate the scene in ``folder`` and write it back (see the module docstring).
    ``requests``: ``[(category or asset id, count), ...]`` or the ``"mug:2,book"`` text form;
    None draws ``count`` objects from what sits on such a receptacle in AI2-THOR
    (:mod:`holomj.jobs.receptacle_priors`).

    Raises :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, a bad
    seed or attempt count, an unknown receptacle or request.
    """
    folder = require_scene_folder(Path(folder), "holomj compile' or 'holomj generate")
    if isinstance(requests, str):
        requests = parse_objects(requests)
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"must lie in [0, {MAX_SEED}]", where="--seed")
    if max_attempts < 1 or max_attempts > MAX_ATTEMPTS:
        raise InputError(f"must lie in [1, {MAX_ATTEMPTS}]", where="--max-attempts")
    scene = read_scene(folder)
    libraries = [open_library(folder)]
    if library_path is not None:
        libraries.append(AssetLibrary.open(library_path))
    library = merge_libraries(*libraries)
    drawn_from = None
    if requests is None:
        if not 1 <= count <= MAX_DRAWN:
            raise InputError(f"must lie in [1, {MAX_DRAWN}]", where="--count")
        category = library.get(find_object(scene, receptacle_id).asset).meta.category
        requests, drawn_from = prior_requests(
            category, library, stage_rng(seed, "populate", "priors"), count
        )

    def with_robot(compiled: CompiledScene) -> CompiledScene:
        return attach_folder_robot(compiled, folder)

    result = populate(
        scene,
        library,
        receptacle_id,
        requests,
        seed_rng(seed),
        max_attempts=max_attempts,
        attach=with_robot,
    )
    compiled = with_robot(compile_scene(result.scene, library))
    run = {
        "receptacle": receptacle_id,
        "requests": [{"name": n, "count": c} for n, c in requests],
        "drawn_from": drawn_from,
        "seed": seed,
        "max_attempts": max_attempts,
        **result.to_dict(),
    }
    written: dict[str, Any] = {}
    if (folder / REPORT_JSON).exists():
        validation = _validate(result.scene, library, folder)
        written[REPORT_JSON] = validation.model_dump(mode="json")
        run["validation"] = {
            "ok": validation.ok,
            "furniture": validation.furniture,
            "counts": validation.counts,
        }
    previous = _previous_runs(folder)
    # Kept as they are, but made from the scene before this run.
    stale = [name for name in (RENDERS_DIR, REPORT_HTML) if (folder / name).exists()]
    report = {**run, "runs": [*previous, run], "stale_files": stale}
    written[POPULATE_REPORT] = report
    write_scene_folder(compiled, folder, overwrite=True, extra_json=written, keep_from=folder)
    return PopulateResult(
        folder=str(folder),
        receptacle=receptacle_id,
        requested=run["requested"],
        placed=run["placed"],
        report=report,
    )


def _validate(scene: SceneSpec, library: AssetLibrary, folder: Path) -> StabilityReport:
    """The validation ``holomj validate FOLDER`` makes of ``scene`` (with the folder's robot):
    default thresholds, furniture free, no sleeping."""
    compiled = attach_folder_robot(compile_scene(scene, library, furniture="free"), folder)
    loaded = loaded_from_compiled(compiled, library, folder, folder)
    return validate_loaded(loaded, Thresholds(), "free", sleep=False)


def _previous_runs(folder: Path) -> list[Any]:
    try:
        runs = (read_json_report(folder, POPULATE_REPORT) or {}).get("runs", [])
    except (HolomjError, AttributeError):  # an unreadable earlier report starts a new history
        return []
    return runs if isinstance(runs, list) else []
