"""The Python API, re-exported from :mod:`holomj`: one function per job, keyword arguments that
mirror the command line's options, typed results (the models the JSON files hold), and the
:class:`~holomj.errors.HolomjError` types the command line prints.

Every function loads what it needs when it is called; ``import holomj`` loads none of it.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

from holomj.jobs.scene_reader import Scene as Scene  # holomj.Scene: a scene folder, loaded
from holomj.library.store import AssetLibrary as _StoreLibrary

if TYPE_CHECKING:
    from holomj.jobs.add_robot import AddRobotResult
    from holomj.jobs.compile import CompileReport
    from holomj.jobs.eval import EvalReport
    from holomj.jobs.export import ExportResult
    from holomj.jobs.generate import GenerateResult
    from holomj.jobs.populate import PopulateResult
    from holomj.jobs.refine import RefineResult
    from holomj.jobs.stage_log import Listener
    from holomj.spec.report import StabilityReport


class PublicAssetLibrary(_StoreLibrary):
    """``holomj.AssetLibrary``: an asset library on disk, ``AssetLibrary.open(path)``, or
    ``AssetLibrary.default()``.

    The store's :class:`holomj.library.store.AssetLibrary` plus :meth:`default`, which builds
    the default library through :mod:`holomj.jobs.library`: the library package itself may not
    import that layer, so the public class adds it here.
    """

    @classmethod
    def default(cls) -> PublicAssetLibrary:
        """The default library (``$HOLOMJ_HOME/library``), built on first use like the CLI's."""
        from holomj.jobs.library import resolve_library

        return cls.open(resolve_library(None))


AssetLibrary = PublicAssetLibrary  # the public name (``holomj.AssetLibrary``, README)


def _library_root(library: Path | str | AssetLibrary | None) -> Path:
    from holomj.jobs.library import resolve_library

    return resolve_library(library)


def generate(
    prompt: str,
    out: Path | str,
    *,
    library: Path | str | AssetLibrary | None = None,
    listener: Listener | None = None,
    **options: Any,
) -> GenerateResult:
    """``holomj generate``: a prompt in, a validated scene folder ``out`` written.

    ``options``: the fields of :class:`~holomj.jobs.generate_options.GenerateOptions`, by
    keyword (``seed``, ``planner``, ``overwrite``, ``render``, ``width``, ``height``,
    ``furniture``, ``robot``, ``profile``, ``layout_time``, ...); ``library``: a folder or an
    :class:`AssetLibrary` (default: the default library, built on first use).

    Returns a :class:`~holomj.jobs.generate.GenerateResult` (``.folder``, ``.plan``,
    ``.report`` with ``.ok``, ``.record``, ``.timings``). Raises
    :class:`~holomj.errors.InputError` for an empty or too long prompt or a bad or unknown
    option, :class:`~holomj.errors.OutputExistsError` when ``out`` exists (without
    ``overwrite``), and other :class:`~holomj.errors.HolomjError` types when a stage fails; a
    failed render is recorded in the result (``.render_error``), not raised.
    ``listener(stage, message)`` sees every line of the stage log as it happens.
    """
    from holomj.jobs.generate import GenerateOptions, generate_scene

    root = library.root if isinstance(library, _StoreLibrary) else library
    checked = GenerateOptions.from_keywords(library=None if root is None else Path(root), **options)
    return generate_scene(prompt, Path(out), checked, listener=listener)


def compile(
    source: Path | str,
    out: Path | str,
    *,
    library: Path | str | AssetLibrary | None = None,
    format: str | None = None,
    overwrite: bool = False,
    robot: str | None = None,
    profile: Literal["default", "mjx"] = "default",
    seed: int = 0,
    check_seconds: float = 1.0,
    fix: bool | None = None,
    allow_invalid: bool = False,
) -> CompileReport:
    """``holomj compile``: a holomj ``scene.json``, ProcTHOR/Holodeck house or SceneDef ->
    an MJCF folder ``out``; the format is detected unless ``format`` names it.

    ``fix`` makes the scene stand (objects on the floor or their receptacle, clear of walls
    and each other, settled; default: on for imported houses and SceneDefs, off for holomj
    scenes); a scene that cannot be saved raises
    :class:`~holomj.jobs.compile.SceneUnstableError` unless ``allow_invalid``.

    Returns a :class:`~holomj.jobs.compile.CompileReport`. Raises
    :class:`~holomj.errors.FormatError` / :class:`~holomj.errors.SpecError` for bad input
    (naming file and field), :class:`~holomj.errors.OutputExistsError`,
    :class:`~holomj.errors.AssetNotFoundError`, :class:`~holomj.errors.CompileError`.
    """
    from holomj.jobs.compile import compile_file

    return compile_file(
        Path(source),
        Path(out),
        library_path=_library_root(library),
        fmt=format,
        overwrite=overwrite,
        check_seconds=check_seconds,
        robot=robot,
        profile=profile,
        seed=seed,
        fix=fix,
        allow_invalid=allow_invalid,
    )


def validate(
    scene: Path | str,
    *,
    repair: bool = False,
    furniture: Literal["free", "static", "as-is"] = "free",
    sleep: bool = False,
    tolerance_mm: float = 1.0,
    monitor_s: float = 3.0,
    settle_s: float = 5.0,
) -> StabilityReport:
    """``holomj validate``: audit ``scene`` (a holomj folder, its scene.xml, or any MJCF file)
    at t = 0, settle it and judge every object by the stability rule.

    Returns the :class:`~holomj.spec.report.StabilityReport` (``.ok``, ``.objects``, ...;
    with ``repair``, ``.repaired`` and ``.unsaved``). Raises
    :class:`~holomj.errors.InputError` for bad options or a repair of something that is not
    a holomj folder, :class:`~holomj.errors.FormatError` when the scene cannot be loaded.
    """
    from holomj.jobs.validate import validate as validate_job
    from holomj.spec.report import Thresholds

    thresholds = Thresholds(
        tolerance_m=tolerance_mm / 1000.0, monitor_s=monitor_s, settle_cap_s=settle_s
    )
    return validate_job(
        Path(scene), thresholds=thresholds, furniture=furniture, sleep=sleep, repair=repair
    )


def render(
    folder: Path | str,
    *,
    width: int = 640,
    height: int = 480,
    views: Sequence[str] = ("top", "rooms"),
    depth: bool = False,
    segmentation: bool = False,
    shadows: bool = True,
    report: bool = True,
) -> Any:
    """``holomj render``: ``folder/renders/`` (and ``folder/report.html`` unless ``report`` is
    false), headless. Returns the render summary (files, cameras, timings). Raises
    :class:`~holomj.errors.InputError` for a folder that is not a holomj scene and
    :class:`~holomj.errors.HolomjError` when no OpenGL backend can render."""
    from holomj.jobs.render import render_folder, write_report_html

    summary = render_folder(
        Path(folder),
        width=width,
        height=height,
        views=tuple(views),
        depth=depth,
        segmentation=segmentation,
        shadows=shadows,
    )
    if report:
        write_report_html(Path(folder))
    return summary


def populate(
    folder: Path | str,
    on: str,
    objects: str | list[tuple[str, int]],
    *,
    seed: int = 0,
    library: Path | str | AssetLibrary | None = None,
    max_attempts: int = 20,
) -> PopulateResult:
    """``holomj populate``: drop small objects (``"mug:2,book"`` or ``[("mug", 2)]``) onto the
    receptacle ``on`` of ``folder`` and write the folder back. Returns what was placed
    (``.placed``, ``.requested``, ``.report``). Raises :class:`~holomj.errors.InputError` for
    an unknown receptacle or object, or a bad seed or attempt count."""
    from holomj.jobs.populate import populate_folder

    return populate_folder(
        Path(folder),
        on,
        objects,
        seed=seed,
        library_path=_library_root(library),
        max_attempts=max_attempts,
    )


def add_robot(
    folder: Path | str,
    robot: str,
    *,
    room: str | None = None,
    seed: int = 0,
    clearance: float | None = None,
    replace: bool = False,
    profile: Literal["default", "mjx"] = "default",
) -> AddRobotResult:
    """``holomj add-robot``: attach ``robot`` (``panda``, ``jaco`` or an MJCF path) to the scene
    folder at a free floor spot. Raises :class:`~holomj.errors.InputError` for an unknown robot,
    no free spot, or a folder that has a robot already (without ``replace``)."""
    from holomj.jobs.add_robot import add_robot_to_folder

    return add_robot_to_folder(
        Path(folder),
        robot,
        seed=seed,
        clearance=clearance,
        room=room,
        profile=profile,
        replace=replace,
    )


def export(
    folder: Path | str,
    format: Literal["glb", "usd", "urdf"] = "glb",
    out: Path | str | None = None,
    *,
    colliders: bool = False,
) -> ExportResult:
    """``holomj export``: the scene folder as GLB (the scene as seen, Y-up), USD (a UsdPhysics
    stage; needs the ``export`` extra) or URDF (one per articulated asset), written to ``out``
    (default ``folder/export/scene.glb``, ``scene.usdz`` or ``urdf/``). ``colliders`` (GLB):
    also the collision-only geoms. Returns an :class:`~holomj.jobs.export.ExportResult`
    (``.target``, ``.files``, ``.bytes``, ``.timings_s``, ``.details``). Raises
    :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, an unknown
    format, a target of the wrong kind or a missing usd-core, and
    :class:`~holomj.errors.ExportError` when writing fails."""
    from holomj.jobs.export import export_folder

    return export_folder(
        Path(folder), format, Path(out) if out is not None else None, colliders=colliders
    )


def eval(
    folder: Path | str,
    *,
    prompt: str | None = None,
    spec: Path | str | dict[str, Any] | None = None,
    spec_id: str | None = None,
    validate: bool = False,
    seed: int = 0,
) -> EvalReport:
    """``holomj eval``: measure the scene folder from its geometry: counts, attributes and
    relations against its ``plan.json`` (or the offline plan of ``prompt``, or the annotation
    ``spec``: a dict or a .json/.jsonl file, ``spec_id`` picking one), colliding pairs, objects
    outside their room, support, navigability, front access, doors and windows clear, and
    stability from ``report.json`` (``validate``: validate when it is absent). Returns an
    :class:`~holomj.evaluation.report.EvalReport` (``.scores``, ``.details``, ``.overall``,
    ``.to_json()``); nothing is written. Raises :class:`~holomj.errors.InputError` for a folder
    that is not a holomj scene, both ``prompt`` and ``spec``, or a bad spec."""
    from holomj.jobs.eval import evaluate

    return evaluate(
        Path(folder), prompt=prompt, spec=spec, spec_id=spec_id, validate=validate, seed=seed
    )


def refine(
    folder: Path | str,
    instruction: str,
    *,
    rounds: int = 3,
    planner: Literal["offline", "llm"] = "offline",
    out: Path | str | None = None,
    overwrite: bool = False,
    seed: int = 0,
    library: Path | str | AssetLibrary | None = None,
    llm: Any = None,
    images: bool | None = None,
    max_ops: int | None = None,
    render: bool = True,
) -> RefineResult:
    """``holomj refine``: make the scene folder follow ``instruction`` ("add a reading corner
    with an armchair and a floor lamp by the window") round by round: render, plan edits
    (``planner``: offline, or ``llm``: a vision-language model at an OpenAI-compatible
    endpoint; ``llm``: an :class:`~holomj.plan.llm_config.LLMConfig` or a dict of
    ``base_url``, ``model``, ``api_key``, ``config_file``; ``images=False``: text only), apply
    them to a copy, validate and score it, keep the round when the score does not fall. The
    result goes into ``out`` (default: back into ``folder``) with ``refine.json``.

    Returns a :class:`~holomj.jobs.refine.RefineResult` (``.ok``, ``.score_before``,
    ``.score_after``, ``.rounds``, ``.checks``, ``.record``). Raises
    :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, an empty
    instruction, bad numbers or no LLM configured, and
    :class:`~holomj.errors.OutputExistsError` when ``out`` exists (without ``overwrite``)."""
    from holomj.jobs.refine import refine as refine_folder

    return refine_folder(
        Path(folder),
        instruction,
        rounds=rounds,
        planner=planner,
        out=out,
        overwrite=overwrite,
        seed=seed,
        library_path=_library_root(library),
        llm_config=llm,
        images=images,
        max_ops=max_ops,
        render=render,
    )
