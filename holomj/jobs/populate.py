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

**With an instruction** (``instruction="a mug and two books for a reading break"``, no
``requests``): with ``planner="llm"`` the model picks and places the objects by pointing at a
render of the receptacle (:mod:`holomj.jobs.pointing`); offline (``planner="offline"``, or no
LLM configured: the report says so) the instruction's small objects that the libraries hold
are dropped, and the receptacle priors decide when it names none.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from holomj.errors import HolomjError, InputError
from holomj.file_names import POPULATE_REPORT, RENDERS_DIR, REPORT_HTML, REPORT_JSON
from holomj.jobs.folder import (
    PreparedOutput,
    attach_folder_robot,
    open_library,
    prepare_output,
    read_json_report,
    read_scene,
    require_scene_folder,
    write_scene_folder,
)
from holomj.jobs.plan import check_planner
from holomj.jobs.receptacle_priors import DEFAULT_COUNT, instruction_requests, prior_requests
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.physics.scene_io import loaded_from_compiled
from holomj.physics.settle import validate_loaded
from holomj.physics.spawn import populate
from holomj.physics.spawn_requests import find_object, merge_libraries
from holomj.seeds import MAX_SEED, seed_rng, stage_rng
from holomj.spec.populate_report import (
    PopulateReport,
    PopulateRun,
    PopulateValidation,
    RequestedCount,
)
from holomj.spec.report import StabilityReport, Thresholds
from holomj.spec.scene import SceneSpec

if TYPE_CHECKING:
    from holomj.jobs.pointing import PointingOutcome
    from holomj.refinement.llm import VisionChat

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
    report: PopulateReport

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
    instruction: str | None = None,
    planner: str = "offline",
    llm_config: Any = None,
    images: bool | None = None,
    log: Callable[[str], None] | None = None,
) -> PopulateResult:
    """Populate the scene in ``folder`` and write it back (see the module docstring).
    ``requests``: ``[(category or asset id, count), ...]`` or the ``"mug:2,book"`` text form;
    None draws ``count`` objects from what sits on such a receptacle in AI2-THOR
    (:mod:`holomj.jobs.receptacle_priors`), or, with ``instruction``, up to ``count`` objects
    the instruction asks for (``planner="llm"``: named and pointed at by the model;
    ``llm_config``: a :class:`holomj.plan.llm_config.LLMConfig`, default from the environment
    and ``$HOLOMJ_HOME/config.toml``; ``images``: send the renders, default yes).

    Raises :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, a bad
    seed or attempt count, an unknown receptacle or request, both ``requests`` and
    ``instruction``, or an unknown planner.
    """
    folder = require_scene_folder(Path(folder), "holomj compile' or 'holomj generate")
    prepared = prepare_output(folder, overwrite=True)  # rewritable, before any work
    requests, instruction = _checked_arguments(requests, instruction, planner, seed, max_attempts)
    scene = read_scene(folder)
    libraries = [open_library(folder)]
    if library_path is not None:
        libraries.append(AssetLibrary.open(library_path))
    library = merge_libraries(*libraries)
    notes: list[str] = []

    def with_robot(compiled: CompiledScene) -> CompiledScene:
        return attach_folder_robot(compiled, folder)

    chat = None
    if instruction is not None and requests is None and planner == "llm":
        chat, why = _chat(llm_config, images, seed, log)
        if chat is None:
            notes.append(f"no LLM to point with ({why}): the offline planner decided")
    if chat is not None:
        result_scene, run = _run_pointing(
            folder, scene, receptacle_id, instruction or "", count, chat, libraries,
            seed, max_attempts, with_robot, log,
        )  # fmt: skip
        library = merge_libraries(*libraries)  # with the assets made on demand
    else:
        result_scene, run = _run_drops(
            scene, library, receptacle_id, requests, instruction, count, seed, max_attempts,
            with_robot,
        )  # fmt: skip
    added: dict[str, Any] = {}
    if instruction is not None:
        added["instruction"] = instruction
        added["planner"] = "llm" if chat is not None else "offline"
    if notes:
        added["notes"] = notes
    run = run.model_copy(update=added)
    report = _write_populated(folder, prepared, result_scene, library, run, with_robot)
    return PopulateResult(
        folder=str(folder),
        receptacle=receptacle_id,
        requested=run.requested,
        placed=run.placed,
        report=report,
    )


def _run_pointing(
    folder: Path,
    scene: SceneSpec,
    receptacle_id: str,
    instruction: str,
    count: int,
    chat: VisionChat,
    libraries: list[AssetLibrary],
    seed: int,
    max_attempts: int,
    with_robot: Callable[[CompiledScene], CompiledScene],
    log: Callable[[str], None] | None,
) -> tuple[SceneSpec, PopulateRun]:
    """The model names each object and points at where it goes; the populated scene and the
    run's report. Assets made on demand are added to ``libraries[0]`` (the folder's)."""
    _check_count(count)
    from holomj.jobs.pointing import populate_by_pointing

    find_object(scene, receptacle_id)
    pointed = populate_by_pointing(
        folder,
        scene,
        receptacle_id,
        instruction,
        count=count,
        chat=chat,
        own=libraries[0],
        source=libraries[1] if len(libraries) > 1 else None,
        seed=seed,
        max_attempts=max_attempts,
        attach=with_robot,
        log=log,
    )
    return pointed.scene, _pointing_run(pointed, chat, receptacle_id, seed, max_attempts)


def _run_drops(
    scene: SceneSpec,
    library: AssetLibrary,
    receptacle_id: str,
    requests: list[tuple[str, int]] | None,
    instruction: str | None,
    count: int,
    seed: int,
    max_attempts: int,
    with_robot: Callable[[CompiledScene], CompiledScene],
) -> tuple[SceneSpec, PopulateRun]:
    """Spawn-and-drop the requests (drawn when None); the populated scene and the run's
    report."""
    drawn_from = None
    if requests is None:
        requests, drawn_from = _drawn_requests(
            scene, library, receptacle_id, instruction, count, seed
        )
    result = populate(
        scene,
        library,
        receptacle_id,
        requests,
        seed_rng(seed),
        max_attempts=max_attempts,
        attach=with_robot,
    )
    run = PopulateRun(
        receptacle=receptacle_id,
        requests=[RequestedCount(name=n, count=c) for n, c in requests],
        drawn_from=drawn_from,
        seed=seed,
        max_attempts=max_attempts,
        **result.to_dict(),
    )
    return result.scene, run


def _checked_arguments(
    requests: list[tuple[str, int]] | str | None,
    instruction: str | None,
    planner: str,
    seed: int,
    max_attempts: int,
) -> tuple[list[tuple[str, int]] | None, str | None]:
    """The requests (parsed from their text form) and the instruction (whitespace collapsed),
    after checking the arguments that do not need the scene."""
    if isinstance(requests, str):
        requests = parse_objects(requests)
    if instruction is not None:
        instruction = " ".join(instruction.split())
        if not instruction:
            raise InputError("empty instruction", where="--instruction")
        if requests is not None:
            raise InputError("give --objects or --instruction, not both", where="--instruction")
    check_planner(planner)
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"must lie in [0, {MAX_SEED}]", where="--seed")
    if max_attempts < 1 or max_attempts > MAX_ATTEMPTS:
        raise InputError(f"must lie in [1, {MAX_ATTEMPTS}]", where="--max-attempts")
    return requests, instruction


def _check_count(count: int) -> None:
    if not 1 <= count <= MAX_DRAWN:
        raise InputError(f"must lie in [1, {MAX_DRAWN}]", where="--count")


def _drawn_requests(
    scene: SceneSpec,
    library: AssetLibrary,
    receptacle_id: str,
    instruction: str | None,
    count: int,
    seed: int,
) -> tuple[list[tuple[str, int]], str | None]:
    """Requests when none were given: the instruction's small objects the library holds, else
    ``count`` drawn from the receptacle priors; with where they were drawn from."""
    _check_count(count)
    category = library.get(find_object(scene, receptacle_id).asset).meta.category
    if instruction is not None:
        requests = instruction_requests(instruction, library, count)
        if requests:
            return requests, "instruction"
    return prior_requests(category, library, stage_rng(seed, "populate", "priors"), count)


def _pointing_run(
    pointed: PointingOutcome, chat: VisionChat, receptacle_id: str, seed: int, max_attempts: int
) -> PopulateRun:
    """The report of a run in which the model pointed at where each object goes."""
    placements = [
        {
            "object_id": r.get("object_id"),
            "asset": r.get("asset"),
            "accepted": r.get("status") == "placed",
            "reason": r.get("reason", r.get("status")),
            "attempts": r.get("attempts", 0),
        }
        for r in pointed.records
        if r.get("status") != "done"
    ]
    return PopulateRun(
        receptacle=receptacle_id,
        requests=[
            RequestedCount(name=r["name"], count=1) for r in pointed.records if r.get("name")
        ],
        drawn_from="llm pointing",
        seed=seed,
        max_attempts=max_attempts,
        requested=len(placements),
        placed=pointed.placed,
        placements=placements,
        pointing=pointed.records,
        llm={
            "model": chat.config.model,
            "images": chat.images,
            "text_only_reason": chat.text_only_reason,
            **pointed.usage,
        },
    )


def _write_populated(
    folder: Path,
    prepared: PreparedOutput,
    scene: SceneSpec,
    library: AssetLibrary,
    run: PopulateRun,
    with_robot: Callable[[CompiledScene], CompiledScene],
) -> PopulateReport:
    """Compile the populated scene and write it back into ``folder`` (``prepared`` for writing)
    with its validation (when the folder had one) and the populate report; returns the
    report."""
    compiled = with_robot(compile_scene(scene, library))
    written: dict[str, Any] = {}
    if (folder / REPORT_JSON).exists():
        validation = _validate(scene, library, folder)
        written[REPORT_JSON] = validation.model_dump(mode="json")
        checked = PopulateValidation(
            ok=validation.ok, furniture=validation.furniture, counts=validation.counts
        )
        run = run.model_copy(update={"validation": checked})
    previous = _previous_runs(folder)
    # Kept as they are, but made from the scene before this run.
    stale = [name for name in (RENDERS_DIR, REPORT_HTML) if (folder / name).exists()]
    this_run = run.to_dict()
    report = PopulateReport(**this_run, runs=[*previous, this_run], stale_files=stale)
    written[POPULATE_REPORT] = report.to_dict()
    write_scene_folder(compiled, prepared, extra_json=written, keep_from=folder)
    return report


def _chat(
    config: Any, images: bool | None, seed: int, log: Callable[[str], None] | None
) -> tuple[VisionChat | None, str]:
    """The model to point with, or (None, why not) when none is configured."""
    from holomj.jobs.refine import resolve_llm_config
    from holomj.refinement.llm import VisionChat, images_enabled

    try:
        config = resolve_llm_config(config)
    except InputError as err:
        return None, err.one_line()
    return VisionChat(config, images=images_enabled(images), seed=seed, log=log), ""


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
