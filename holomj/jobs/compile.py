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
compiles any input as imported).

A house is never thrown away for what can be fixed or honestly left out
(:mod:`holomj.physics.standing.keep`): an object that cannot stand where it was authored moves
to another receptacle of the same kind, else it is left out; each is recorded in
``import_report.json`` (``relocated``, ``left_out``: from where, to where, why). Refused
(:class:`SceneUnstableError`, exit code 1, nothing written) unless ``allow_invalid`` (which
writes it marked ``"valid": false``): a house that keeps less than :data:`MIN_KEPT_SHARE` of
its objects, one that leaves any object out with ``strict``, one that still does not validate.
"""

from __future__ import annotations

import dataclasses
import json
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from holomj.errors import HolomjError
from holomj.file_names import IMPORT_REPORT, REPORT_JSON
from holomj.formats.summaries import ModelSummary, SceneSummary, model_summary, scene_summary
from holomj.importers.result import ImportResult
from holomj.jobs.folder import prepare_output, write_scene_folder
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, Profile, check_profile, compile_scene
from holomj.mjcf.objects import Furniture
from holomj.physics.smoke import simulate
from holomj.physics.standing.keep import KeptHouse, make_stand_keeping
from holomj.spec.report import StabilityReport
from holomj.spec.robot import RobotRecord
from holomj.spec.scene import SceneSpec
from holomj.spec.stand_record import StandRecord

FIXED_FORMATS = ("procthor", "holodeck", "scenedef")  # made to stand unless fix=False
MAX_NAMED = 8  # unsaved objects named in the error message
MIN_KEPT_SHARE = 0.97  # a house keeps at least this share of its objects


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
    stand: StandRecord | None = None  # what making it stand changed (None: not run)
    merged: list[dict[str, str]] = field(default_factory=list)  # fixtures of a stand-in

    @property
    def valid(self) -> bool | None:
        """Whether the written scene stands (None when it was not made to stand)."""
        return None if self.stand is None else self.stand.valid

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form."""
        robot = None if self.robot is None else dataclasses.asdict(self.robot)
        return {
            **self.__dict__,
            "scene": self.scene.to_dict(),
            "model": self.model.to_dict(),
            "robot": robot,
            "stand": None if self.stand is None else self.stand.to_dict(),
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
    strict: bool = False,
    objathor: Path | None = None,
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
    :class:`SceneUnstableError` (nothing written) when it does not stand, keeps too little or,
    with ``strict``, leaves anything out, unless ``allow_invalid``. ``objathor``: a folder
    whose Objaverse assets the house names are imported into the library first.
    """
    timings: dict[str, float] = {}
    checked_profile = check_profile(profile)
    prepared = prepare_output(out, overwrite)
    start = time.perf_counter()
    library, result, objathor_note = _import(Path(input_path), fmt, library_path, objathor)
    timings["import"] = time.perf_counter() - start
    start = time.perf_counter()
    build = _Builder(library, checked_profile, robot, seed)
    stand, refusal = None, None
    if fix if fix is not None else result.format in FIXED_FORMATS:
        stand, refusal = _make_stand(
            result.scene, library, build, Path(input_path), out, (allow_invalid, strict)
        )
        compiled = stand.outcome.compiled
        timings["stand"] = time.perf_counter() - start
    else:
        compiled = build(result.scene, "as-is")
        timings["compile"] = time.perf_counter() - start
    sim_warnings: dict[str, int] = {}
    if check_seconds > 0:
        start = time.perf_counter()
        sim_warnings = simulate(compiled.model, check_seconds).warnings
        timings["check"] = time.perf_counter() - start
    stand_record = None if stand is None else _stand_record(stand, refusal, allow_invalid, strict)
    files = _report_files(result, sim_warnings, stand, stand_record)
    start = time.perf_counter()
    write_scene_folder(compiled, prepared, extra_json=files)
    timings["export"] = time.perf_counter() - start
    return CompileReport(
        input=str(input_path),
        output=str(out),
        format=result.format,
        scene=scene_summary(result.scene),
        model=model_summary(compiled.model),
        substitutions=[s.__dict__ for s in result.substitutions],
        merged=list(result.merged),
        warnings=[*([objathor_note] if objathor_note else []), *result.warnings],
        sim_warnings=sim_warnings,
        timings_s={k: round(v, 4) for k, v in timings.items()},
        robot=_robot_summary(compiled.robot),
        stand=stand_record,
    )


def _import(
    input_path: Path, fmt: str | None, library_path: Path | None, objathor: Path | None
) -> tuple[AssetLibrary, ImportResult, str | None]:
    """The library (with the house's objathor assets imported into it first, when asked),
    the imported scene, and a note of what ``objathor`` brought."""
    from holomj.importers import load_scene_input

    note = None
    if objathor is not None:
        library_path, note = _objathor_assets(input_path, objathor, library_path)
    library = AssetLibrary.open(library_path)
    return library, load_scene_input(input_path, library, fmt), note


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


def _report_files(
    result: ImportResult,
    sim_warnings: dict[str, int],
    stand: KeptHouse | None,
    stand_record: StandRecord | None,
) -> dict[str, Any]:
    """``import_report.json`` and, when the house was made to stand, ``report.json``."""
    files: dict[str, Any] = {
        IMPORT_REPORT: {
            **result.to_report(),
            "simulation_warnings": sim_warnings,
            **(stand_record.to_dict() if stand_record is not None else {}),
        }
    }
    if stand is not None and stand.outcome.report is not None:
        files[REPORT_JSON] = stand.outcome.report.model_dump(mode="json")
    return files


def _stand_record(
    stand: KeptHouse, refusal: str | None, allow_invalid: bool, strict: bool
) -> StandRecord:
    """What making the house stand changed, for ``import_report.json`` and the report."""
    return StandRecord(
        **{
            **stand.outcome.to_report(),
            **stand.to_report(),
            "valid": stand.outcome.valid and refusal is None,
            "refusal": refusal,
            "allow_invalid": allow_invalid,
            "strict": strict,
        }
    )


def _make_stand(
    scene: SceneSpec,
    library: AssetLibrary,
    build: _Builder,
    source: Path,
    out: Path,
    flags: tuple[bool, bool],
) -> tuple[KeptHouse, str | None]:
    """The scene made to stand, moving or leaving out what cannot (its validation report
    names ``out``, as ``holomj validate OUT`` would); :class:`SceneUnstableError` when it
    does not stand, keeps too little or (``strict``) leaves anything out, unless
    ``allow_invalid`` (``flags``: ``(allow_invalid, strict)``); then the reason it would
    have been refused comes with it (None when it stands)."""
    allow_invalid, strict = flags
    kept = make_stand_keeping(scene, library, build, source=out)
    problem = _refusal(kept, strict)
    if problem is not None and not allow_invalid:
        raise SceneUnstableError(
            problem,
            where=str(source),
            fix="nothing was written; pass --allow-invalid to write the scene anyway "
            "(marked invalid in import_report.json), or --no-fix to compile it as imported",
        )
    return kept, problem


def _refusal(kept: KeptHouse, strict: bool) -> str | None:
    """Why the house is refused, or None."""
    outcome, left = kept.outcome, kept.left_out
    if strict and left:
        return f"--strict: {len(left)} object(s) would be left out: {_named(left)}"
    if kept.kept_share < MIN_KEPT_SHARE:
        return (
            f"the house keeps only {kept.kept_share:.1%} of its {kept.imported} objects "
            f"(at least {MIN_KEPT_SHARE:.0%} needed); left out: {_named(left)}"
        )
    if outcome.valid:
        return None
    if outcome.unsaved:
        rows = [{"object": u.name, "why": u.why} for u in outcome.unsaved]
        return f"{len(rows)} object(s) could not be made to stand: {_named(rows)}"
    return f"the scene does not validate: {_verdict(outcome.report)}"


def _named(rows: list[dict[str, Any]]) -> str:
    named = "; ".join(f"{r['object']} ({r['why']})" for r in rows[:MAX_NAMED])
    more = len(rows) - MAX_NAMED
    return named + (f"; and {more} more" if more > 0 else "")


def _objathor_assets(
    house: Path, directory: Path, library_path: Path | None
) -> tuple[Path | None, str]:
    """Import into the library the assets of ``directory`` that ``house`` names by uid; the
    library to use and a note of what was imported."""
    from holomj.jobs.objathor import import_objathor

    try:
        data = json.loads(house.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return library_path, "--objathor: the house could not be read for its asset ids"
    assets = directory / "assets" if (directory / "assets").is_dir() else directory
    named = sorted(_asset_ids(data.get("objects") if isinstance(data, dict) else None))
    present = [uid for uid in named if (assets / uid).is_dir()]
    if not present:
        return (
            library_path,
            f"--objathor: none of the house's {len(named)} asset ids is in {assets}",
        )
    imported = import_objathor(directory, library=library_path, uids=present)
    return imported.library, (
        f"--objathor: {len(present)} of the house's {len(named)} asset ids imported from {assets}"
    )


def _asset_ids(objects: Any) -> set[str]:
    """The ``assetId`` of every object and nested child."""
    found: set[str] = set()
    for obj in objects if isinstance(objects, list) else ():
        if isinstance(obj, dict):
            if isinstance(obj.get("assetId"), str):
                found.add(obj["assetId"])
            found |= _asset_ids(obj.get("children"))
    return found


def _verdict(report: StabilityReport | None) -> str:
    if report is None:
        return "not validated"
    return f"{report.counts.get('penetrations', 0)} penetrations, warnings {report.warnings}"


def _robot_summary(record: RobotRecord | None) -> RobotSpot | None:
    """Name, spot and room of the attached robot (None without one)."""
    if record is None:
        return None
    return RobotSpot(record.name, list(record.position), record.yaw_deg, record.room)
