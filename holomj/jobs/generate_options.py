"""The options of ``generate`` (declared once: :class:`GenerateOptions`) and every check of a
request, run once, before any work (:func:`check_request`)."""

from __future__ import annotations

from dataclasses import dataclass, fields
from pathlib import Path
from typing import TYPE_CHECKING, Any

from holomj.errors import InputError
from holomj.jobs.folder import PreparedOutput, prepare_output
from holomj.jobs.plan import PlanOptions, check_planner
from holomj.mjcf.compiler import Profile, check_profile

if TYPE_CHECKING:
    from holomj.robots.registry import RobotSource

MAX_PROMPT_CHARS = 2000
FURNITURE_MODES = ("free", "static")


@dataclass(frozen=True, kw_only=True)
class GenerateOptions(PlanOptions):
    """Everything ``generate`` needs besides the prompt and the output folder: the one
    declaration of generate's options (the plan stage's own are :class:`PlanOptions`'s; the
    Python API takes these as keywords, the command line builds it)."""

    library: Path | None = None  # the asset library (default: the default one, built on first use)
    overwrite: bool = False
    render: bool = True
    width: int = 640  # render size in pixels
    height: int = 480
    clip_weights: Path | None = None
    clip_model: str | None = None
    materials: Path | None = None
    layout_time: float = 1.0  # layout solver seconds per room
    sleep: bool = True
    # free: furniture simulated free in validation, but for the bolted-down fixtures
    # (holomj.layout.furniture_rules.FIXED_CATEGORIES, static in the scene); static: all fixed.
    furniture: str = "free"
    robot: str | None = None  # registry name or MJCF path, attached before validation
    profile: str = "default"  # compile profile: default or mjx
    # articulated storage (fridges, cabinets, drawers) also gets small objects inside
    # (holomj.compose.small_objects: holomj/data/small_objects_inside.json)
    inside: bool = True

    @classmethod
    def from_keywords(cls, **options: Any) -> GenerateOptions:
        """The options named by keyword; an InputError naming any unknown one."""
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(options) - known)
        if unknown:
            raise InputError(
                f"unknown option {unknown[0]!r}",
                where="generate",
                fix=f"use one of: {', '.join(sorted(known))}",
            )
        return cls(**options)

    def plan_options(self) -> PlanOptions:
        """The subset of these options the plan stage reads."""
        return PlanOptions(**{f.name: getattr(self, f.name) for f in fields(PlanOptions)})


@dataclass(frozen=True)
class CheckedRequest:
    """What :func:`check_request` found valid: the output folder, the compile profile and the
    robot to attach (None: none)."""

    out: PreparedOutput
    profile: Profile
    robot: RobotSource | None


def check_request(prompt: str, out: Path, options: GenerateOptions) -> CheckedRequest:
    """Every check of a generate request, before any work: the prompt, the planner, the
    furniture mode, the compile profile, the robot and the output folder (one-line InputErrors,
    exit code 2)."""
    if not prompt.strip():
        raise InputError("the prompt is empty", where="PROMPT", fix='e.g. "a small kitchen"')
    if len(prompt) > MAX_PROMPT_CHARS:
        raise InputError(
            f"the prompt has {len(prompt)} characters, more than {MAX_PROMPT_CHARS}",
            where="PROMPT",
        )
    check_planner(options.planner)
    if options.furniture not in FURNITURE_MODES:
        raise InputError(
            f"unknown value {options.furniture!r}", where="--furniture", fix="use free or static"
        )
    profile = check_profile(options.profile)
    robot = None
    if options.robot is not None:
        from holomj.robots.registry import resolve_robot

        robot = resolve_robot(options.robot)
    return CheckedRequest(prepare_output(Path(out), options.overwrite), profile, robot)
