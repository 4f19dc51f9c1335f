"""The compile job: any supported scene input -> a MJCF folder that stands (or a clear refusal).

``compile_file`` imports the input (holomj ``scene.json``, ProcTHOR/Holodeck house, 3D-Generalist
SceneDef), makes an imported scene stand (:mod:`holomj.physics.standing`: objects on the floor
or dropped onto their receptacles, clear of walls and of each other, settled, with a
``settled`` keyframe, validated as ``holomj validate`` does), compiles it, optionally attaches
a robot, runs a short smoke simulation for MuJoCo warnings and writes the folder atomically
with ``import_report.json`` (and ``report.json``, the final validation).

Which inputs are made to stand: ProcTHOR/Holodeck houses and SceneDefs by default (their
coordinates were authored for other assets and another engine); a holomj ``scene.json`` is
the source of truth and is compiled as it is (``fix=True`` makes it stand too, ``fix=False``
compiles any input as imported). A scene with objects the stage cannot save is refused
(:class:`SceneUnstableError`, exit code 1, nothing written) unless ``allow_invalid``, which
writes it marked ``"valid": false`` in ``import_report.json``.
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from holomj.errors import HolomjError
from holomj.file_names import IMPORT_REPORT, REPORT_JSON
from holomj.formats.summaries import ModelSummary, SceneSummary, model_summary, scene_summary
from holomj.jobs.folder import prepare_output, write_scene_folder
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, Profile, check_profile, compile_scene
from holomj.mjcf.objects import Furniture
from holomj.physics.smoke import simulate
from holomj.physics.standing import StandOutcome, make_stand
from holomj.spec.report import StabilityReport
from holomj.spec.robot import RobotRecord
from holomj.spec.scene import SceneSpec

FIXED_FORMATS = ("procthor", "holodeck", "scenedef")  # made to stand unless fix=False
MAX_NAMED = 8  # unsaved objects named in the error message


class SceneUnstableError(HolomjError):
    """Objects of an imported scene could not be made to stand. Exit code 1."""


@dataclass(frozen=True)
class RobotSpot:
    """The robot a compile attached: its name, where its base stands, its heading and room."""

    name: str
    position: list[float]
    yaw_deg: float
    room: str | None


@dataclass
class CompileReport:
    """What ``compile_file`` did, for people (``summary``) and scripts (``to_dict``)."""

    input: str
    output: str
    format: str
    scene: SceneSummary
    model: ModelSummary
    substitutions: list[dict[str, Any]]
    warnings: list[str]
    sim_warnings: dict[str, int]
    timings_s: dict[str, float] = field(default_factory=dict)
    robot: RobotSpot | None = None
    stand: dict[str, Any] | None = None  # what making it stand changed (None: not run)
    merged: list[dict[str, str]] = field(default_factory=list)  # fixtures of a stand-in

    @property
    def valid(self) -> bool | None:
        """Whether the written scene stands (None when it was not made to stand)."""
        return None if self.stand is None else bool(self.stand["valid"])

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form."""
        robot = None if self.robot is None else dataclasses.asdict(self.robot)
        return {
            **self.__dict__,
            "scene": self.scene.to_dict(),
            "model": self.model.to_dict(),
            "robot": robot,
        }


def compile_file(
    input_path: Path,
    out: Path,
    *,
    library_path: Path | None = None,
    fmt: str | None = None,
    overwrite: bool = False,
    check_seconds: float = 1.0,
    robot: str | None = None,
    profile: str = "default",
    seed: int = 0,
    fix: bool | None = None,
    allow_invalid: bool = False,
) -> CompileReport:
    """Import ``input_path`` (any supported format), compile it and export it to ``out``.

    Raises :class:`~holomj.errors.OutputExistsError` when ``out`` exists (unless
    ``overwrite``), :class:`~holomj.errors.FormatError` / :class:`~holomj.errors.SpecError` for
    bad input (naming the file and field), :class:`~holomj.errors.AssetNotFoundError` for an
    asset the library lacks, :class:`~holomj.errors.CompileError` when MuJoCo rejects it.

    ``check_seconds`` of simulation run after compiling (0 to skip); MuJoCo warnings it raises
    are listed in the report and in ``import_report.json``. ``robot`` (a registry name or an
    MJCF path) is attached on a free floor spot drawn with ``seed``; ``profile`` is the compile
    profile (``default`` or ``mjx``).

    ``fix`` (None: by format, see the module docstring) makes the scene stand; the report's
    ``stand`` (and ``import_report.json``) lists every change. Raises
    :class:`SceneUnstableError` naming the objects it could not save, before anything is
    written, unless ``allow_invalid``.
    """
    from holomj.importers import load_scene_input

    timings: dict[str, float] = {}
    checked_profile = check_profile(profile)
    prepare_output(out, overwrite)
    start = time.perf_counter()
    library = AssetLibrary.open(library_path)
    result = load_scene_input(Path(input_path), library, fmt)
    timings["import"] = time.perf_counter() - start
    start = time.perf_counter()
    build = _Builder(library, checked_profile, robot, seed)
    stand = None
    if fix if fix is not None else result.format in FIXED_FORMATS:
        stand = _make_stand(result.scene, library, build, Path(input_path), out, allow_invalid)
        compiled = stand.compiled
        timings["stand"] = time.perf_counter() - start
    else:
        compiled = build(result.scene, "as-is")
        timings["compile"] = time.perf_counter() - start
    sim_warnings: dict[str, int] = {}
    if check_seconds > 0:
        start = time.perf_counter()
        sim_warnings = simulate(compiled.model, check_seconds).warnings
        timings["check"] = time.perf_counter() - start
    report_json = {**result.to_report(), "simulation_warnings": sim_warnings}
    extra: dict[str, Any] = {}
    stand_record = None
    if stand is not None:
        stand_record = {**stand.to_report(), "allow_invalid": allow_invalid}
        report_json.update(stand_record)
        if stand.report is not None:
            extra[REPORT_JSON] = stand.report.model_dump(mode="json")
    start = time.perf_counter()
    write_scene_folder(
        compiled, out, overwrite=overwrite, extra_json={IMPORT_REPORT: report_json, **extra}
    )
    timings["export"] = time.perf_counter() - start
    return CompileReport(
        input=str(input_path),
        output=str(out),
        format=result.format,
        scene=scene_summary(result.scene),
        model=model_summary(compiled.model),
        substitutions=[s.__dict__ for s in result.substitutions],
        merged=list(result.merged),
        warnings=list(result.warnings),
        sim_warnings=sim_warnings,
        timings_s={k: round(v, 4) for k, v in timings.items()},
        robot=_robot_summary(compiled.robot),
        stand=stand_record,
    )


class _Builder:
    """Compiles the scene to write (``as-is``) and to validate (``free``) in the chosen
    profile; the robot, when asked for, is placed on the first build and carried over."""

    def __init__(
        self, library: AssetLibrary, profile: Profile, robot: str | None, seed: int
    ) -> None:
        self.library = library
        self.profile = profile
        self.robot = robot
        self.seed = seed
        self.first: CompiledScene | None = None

    def __call__(self, scene: SceneSpec, furniture: Furniture) -> CompiledScene:
        compiled = compile_scene(scene, self.library, furniture=furniture, profile=self.profile)
        if self.robot is None:
            return compiled
        if self.first is None:
            from holomj.robots.attach import add_robot
            from holomj.seeds import stage_rng

            self.first = add_robot(compiled, self.robot, stage_rng(self.seed, "robot"))
            return self.first
        from holomj.robots.attach import reattach_robot

        return reattach_robot(compiled, self.first)


def _make_stand(
    scene: SceneSpec,
    library: AssetLibrary,
    build: _Builder,
    source: Path,
    out: Path,
    allow_invalid: bool,
) -> StandOutcome:
    """The scene made to stand (its validation report names ``out``, as ``holomj validate
    OUT`` would); :class:`SceneUnstableError` when it does not stand, unless
    ``allow_invalid``."""
    outcome = make_stand(scene, library, build, validate_unsaved=allow_invalid, source=out)
    if not outcome.valid and not allow_invalid:
        named = "; ".join(f"{u.name} ({u.why})" for u in outcome.unsaved[:MAX_NAMED])
        more = len(outcome.unsaved) - MAX_NAMED
        if more > 0:
            named += f"; and {more} more"
        what = (
            f"{len(outcome.unsaved)} object(s) could not be made to stand: {named}"
            if outcome.unsaved
            else f"the scene does not validate: {_verdict(outcome.report)}"
        )
        raise SceneUnstableError(
            what,
            where=str(source),
            fix="nothing was written; pass --allow-invalid to write the scene anyway "
            "(marked invalid in import_report.json), or --no-fix to compile it as imported",
        )
    return outcome


def _verdict(report: StabilityReport | None) -> str:
    if report is None:
        return "not validated"
    return f"{report.counts.get('penetrations', 0)} penetrations, warnings {report.warnings}"


def _robot_summary(record: RobotRecord | None) -> RobotSpot | None:
    """Name, spot and room of the attached robot (None without one)."""
    if record is None:
        return None
    return RobotSpot(record.name, list(record.position), record.yaw_deg, record.room)
