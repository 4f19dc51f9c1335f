"""The compile job: any supported scene input -> a validated-to-load MJCF folder.

``compile_file`` imports the input (holomj ``scene.json``, ProcTHOR/Holodeck house, 3D-Generalist
SceneDef), compiles it, optionally attaches a robot, runs a short smoke simulation for MuJoCo
warnings and writes the folder atomically with ``import_report.json``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from holomj.export.summaries import model_summary, scene_summary
from holomj.jobs.folder import IMPORT_REPORT, prepare_output, write_scene_folder
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import check_profile, compile_scene
from holomj.physics.smoke import simulate


@dataclass
class CompileReport:
    """What ``compile_file`` did, for people (``summary``) and scripts (``to_dict``)."""

    input: str
    output: str
    format: str
    scene: dict[str, Any]
    model: dict[str, Any]
    substitutions: list[dict[str, Any]]
    warnings: list[str]
    sim_warnings: dict[str, int]
    timings_s: dict[str, float] = field(default_factory=dict)
    robot: dict[str, Any] | None = None

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form."""
        return dict(self.__dict__)


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
    compiled = compile_scene(result.scene, library, profile=checked_profile)
    timings["compile"] = time.perf_counter() - start
    if robot is not None:
        from holomj.robots.attach import add_robot
        from holomj.seeds import stage_rng

        start = time.perf_counter()
        compiled = add_robot(compiled, robot, stage_rng(seed, "robot"))
        timings["robot"] = time.perf_counter() - start
    sim_warnings: dict[str, int] = {}
    if check_seconds > 0:
        start = time.perf_counter()
        sim_warnings = simulate(compiled.model, check_seconds).warnings
        timings["check"] = time.perf_counter() - start
    report_json = {**result.to_report(), "simulation_warnings": sim_warnings}
    start = time.perf_counter()
    write_scene_folder(compiled, out, overwrite=overwrite, extra_json={IMPORT_REPORT: report_json})
    timings["export"] = time.perf_counter() - start
    return CompileReport(
        input=str(input_path),
        output=str(out),
        format=result.format,
        scene=scene_summary(result.scene),
        model=model_summary(compiled.model),
        substitutions=[s.__dict__ for s in result.substitutions],
        warnings=list(result.warnings),
        sim_warnings=sim_warnings,
        timings_s={k: round(v, 4) for k, v in timings.items()},
        robot=_robot_summary(compiled.robot),
    )


def _robot_summary(record: Any) -> dict[str, Any] | None:
    """Name, spot and room of the attached robot (None without one)."""
    if record is None:
        return None
    return {
        "name": record.name,
        "position": list(record.position),
        "yaw_deg": record.yaw_deg,
        "room": record.room,
    }
