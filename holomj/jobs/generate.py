"""``generate``: a prompt in, a validated scene folder out (the stage runner).

Stages, each timed in the log: plan (offline knowledge base, or an LLM with the offline planner
as fallback) -> retrieve + layout per room (floor plan, doors, windows, materials, furniture,
wall objects) -> small objects (spawn-and-drop: on top of receptacles, and inside articulated
storage with ``GenerateOptions.inside``) -> compile -> validate -> export (atomic) ->
render (optional, after the export; a failed render is recorded and leaves the scene intact).
The scene is compiled once: validation, export and render use that model in memory.

``OUT`` receives ``scene.xml``, ``assets/``, ``scene.json``, ``plan.json``, ``report.json`` (the
validation report, as ``holomj validate`` writes it), ``generate.json`` (what every stage chose
and why, timings) and ``generate.log`` (one line per event).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from holomj.atomic import write_file
from holomj.errors import HolomjError, InputError
from holomj.file_names import GENERATE_JSON, GENERATE_LOG, PLAN_JSON, REPORT_JSON
from holomj.jobs.folder import dump_json, prepare_output, write_scene_folder
from holomj.jobs.plan import PlanOptions, check_planner, make_plan
from holomj.jobs.relation_report import structural_verdicts
from holomj.jobs.stage_log import Listener, StageLog
from holomj.layout.house_shell import build_shell
from holomj.layout.room_furnishing import (
    RoomContext,
    RoomFurniture,
    furnish_room,
    retrieve_room,
)
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, check_profile, compile_scene
from holomj.physics.small_object_drops import drop_small_objects
from holomj.seeds import stage_rng
from holomj.spec.materials import BUILTIN_MATERIALS
from holomj.spec.plan import PlanRoom, ScenePlan
from holomj.spec.report import StabilityReport, Thresholds
from holomj.spec.scene import SceneSpec
from holomj.spec.walls import derive_walls

MAX_PROMPT_CHARS = 2000
GROWTH = 1.25  # a room grows by this factor in area when its defining furniture does not fit
MAX_GROWTH = 2
# ... or when less than this share of its free floor is reachable (the layout's own measure,
# holomj.layout.open_pockets, stricter than the evaluator's: a 0.17 m robot's floor reached
# through passages a 0.25 m one fits)
REGROW_SHARE = 0.95
FURNITURE_MODES = ("free", "static")


@dataclass(frozen=True)
class GenerateOptions:
    """Everything ``generate`` needs besides the prompt and the output folder."""

    library: Path
    seed: int = 0
    planner: Literal["offline", "llm"] = "offline"
    overwrite: bool = False
    render: bool = True
    render_size: tuple[int, int] = (640, 480)
    text_model: Path | None = None
    clip_weights: Path | None = None
    clip_model: str | None = None
    materials: Path | None = None
    llm_base_url: str | None = None
    llm_model: str | None = None
    llm_api_key: str | None = None
    llm_config: Path | None = None
    layout_time_s: float = 1.0
    sleep: bool = True
    # free: furniture simulated free in validation, but for the bolted-down fixtures
    # (furnish.FIXED_CATEGORIES, static in the scene); static: all furniture fixed.
    furniture: Literal["free", "static"] = "free"
    robot: str | None = None  # registry name or MJCF path, attached before validation
    profile: str = "default"  # compile profile: default or mjx
    # articulated storage (fridges, cabinets, drawers) also gets small objects inside
    # (holomj.physics.small_object_drops: holomj/data/small_objects_inside.json)
    inside: bool = True

    def plan_options(self) -> PlanOptions:
        """The subset of these options the plan stage reads."""
        return PlanOptions(
            seed=self.seed,
            planner=self.planner,
            text_model=self.text_model,
            llm_base_url=self.llm_base_url,
            llm_model=self.llm_model,
            llm_api_key=self.llm_api_key,
            llm_config=self.llm_config,
        )


@dataclass
class GenerateResult:
    """What ``generate`` made: the folder, the plan, the validation report, the record."""

    out: Path
    plan: ScenePlan
    report: StabilityReport
    record: dict[str, Any]

    @property
    def folder(self) -> Path:
        """The scene folder written."""
        return self.out

    @property
    def ok(self) -> bool:
        """The scene validated ok."""
        return self.report.ok

    @property
    def render_error(self) -> str | None:
        """Why the render stage failed (None when it succeeded or did not run)."""
        outcome = self.record.get("render")
        return None if not outcome or outcome.get("ok") else str(outcome.get("error"))

    @property
    def timings(self) -> dict[str, float]:
        """Wall time per stage in seconds (as in ``generate.json``)."""
        return self.record["timings_s"]

    def summary(self) -> dict[str, Any]:
        """Short JSON-able summary for the CLI."""
        counts = self.record["counts"]
        return {
            "output": str(self.out),
            "ok": self.report.ok,
            "scene_type": self.plan.scene_type,
            "planner": self.plan.planner,
            "rooms": len(self.plan.rooms),
            "objects": counts,
            "unstable": self.report.counts.get("unstable", 0),
            "penetrations": self.report.counts.get("penetrations", 0),
            "notes": self.record["notes"],
            "timings_s": self.timings,
        }


def scene_name(prompt: str) -> str:
    """A short name for the scene from its prompt."""
    words = re.findall(r"[a-z0-9]+", prompt.lower())[:8]
    return "_".join(words)[:64] or "scene"


def generate_scene(
    prompt: str,
    out: Path,
    options: GenerateOptions,
    *,
    listener: Listener | None = None,
) -> GenerateResult:
    """Run every stage for ``prompt`` and write ``out`` (see the module docstring)."""
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
    out = Path(out)
    prepare_output(out, options.overwrite)
    check_profile(options.profile)
    if options.robot is not None:
        from holomj.robots.registry import resolve_robot

        resolve_robot(options.robot)  # a bad robot fails now, not after the layout
    run = _Run(prompt, out, options, StageLog(listener))
    run.plan_stage()
    run.retrieve_stage()
    run.layout_stage()
    run.small_objects_stage()
    run.validate_stage()
    run.export_stage()
    if options.render:
        run.record["render"] = _render(out, options, run.log, run.compiled)
    _write_log(out / GENERATE_LOG, run.log)
    run.record["timings_s"] = dict(run.log.timings)
    return GenerateResult(out, run.plan, run.report, run.record)


class _Run:
    """The state one generate run passes from stage to stage."""

    def __init__(self, prompt: str, out: Path, options: GenerateOptions, log: StageLog) -> None:
        self.prompt = prompt
        self.out = out
        self.options = options
        self.seed = options.seed
        self.log = log
        self.library = AssetLibrary.open(options.library)
        log.info(
            "setup",
            f"library {self.library.root} ({len(self.library.ids())} assets), seed {self.seed}",
        )

    def plan_stage(self) -> None:
        with self.log.stage("plan"):
            plan = make_plan(
                self.prompt, self.options.plan_options(), self.library.categories(), self.log
            )
            furniture = sum(o.quantity for r in plan.rooms for o in r.objects)
            self.log.info(
                "plan",
                f"{plan.planner} plan: {plan.scene_type} "
                f"({plan.scene_type_match or 'direct'}), {len(plan.rooms)} room(s), "
                f"{furniture} furniture item(s)",
            )
            for note in plan.notes:
                self.log.info("plan", f"note: {note}")
        self.plan = plan

    def retrieve_stage(self) -> None:
        from holomj.jobs.synthesis import LibrarySynthesiser
        from holomj.retrieval.assets import retriever_for
        from holomj.retrieval.materials import material_picker
        from holomj.retrieval.text import text_encoder

        with self.log.stage("retrieve"):
            encoder = text_encoder(self.options.text_model)
            # Assets the library lacks (a category, a colour, a shape) are made on demand into
            # it, or into $HOLOMJ_HOME/synthesised when it is read-only; see
            # holomj.jobs.synthesis.
            self.retriever = retriever_for(
                self.library,
                clip_weights=self.options.clip_weights,
                clip_model=self.options.clip_model,
                encoder=encoder,
                synthesiser=LibrarySynthesiser(self.library),
            )
            self.pick_material = material_picker(encoder=encoder, materials=self.options.materials)
            self.assets = {
                r.id: retrieve_room(r, self.library, self.retriever, self.seed)
                for r in self.plan.rooms
            }
            for note in self.retriever.notes:
                self.log.info("retrieve", note)
            picked = sum(len(a.floor) + len(a.wall) for a in self.assets.values())
            self.log.info("retrieve", f"{picked} asset(s) chosen")

    def layout_stage(self) -> None:
        """Floor plan, openings and furniture. A room whose size the request left open grows (up
        to ``MAX_GROWTH`` times by ``GROWTH`` in area) and the house is laid out again when its
        defining furniture does not fit even with its windows moved, or when its furniture cuts
        off free floor (less than ``REGROW_SHARE`` reachable)."""
        log = self.log
        with log.stage("layout"):
            plan, grown = self.plan, []
            for _ in range(MAX_GROWTH + 1):
                shell, furnished = self._lay_out(plan)
                short = {
                    room.id: why
                    for room, done in zip(plan.rooms, furnished)
                    if room.size is None
                    and room.area_m2 is not None
                    and (why := _why_grow(room, done))
                }
                if not short or len(grown) >= MAX_GROWTH:
                    break
                plan, change = _grow(plan, short)
                grown.append(change)
                log.info("layout", f"changed the plan: {change}; laying out again")
            if grown:
                self.plan = plan
                furnished[0].changes[:0] = grown
            for done in furnished:
                for change in done.changes:
                    log.info("layout", f"changed the plan: {change}")
                lay = done.layout
                log.info(
                    "layout",
                    f"{done.room_id}: {len(done.objects)} object(s) placed, "
                    f"{len(done.unplaced)} not, constraints "
                    f"{lay.get('constraints_satisfied', 0)}/{lay.get('constraints_total', 0)} "
                    f"({lay.get('solver', '-')}, {lay.get('seconds', 0):.2f} s)",
                )
                for item in done.unplaced:
                    log.info(
                        "layout", f"{done.room_id}: not placed: {item['object']}: {item['reason']}"
                    )
            self.furnished = furnished
            # each room's windows as its furnishing left them (a window may have moved)
            order = {w.id: i for i, w in enumerate(shell.windows)}
            windows = sorted((w for r in furnished for w in r.windows), key=lambda w: order[w.id])
            self.shell = shell
            self.scene = SceneSpec(
                name=scene_name(self.prompt),
                wall_height=plan.wall_height,
                rooms=shell.rooms,
                doors=shell.doors,
                windows=windows,
                objects=[o for r in furnished for o in r.objects],
                materials={n: m for n, m in shell.materials.items() if n not in BUILTIN_MATERIALS},
                source=f"holomj generate (seed {self.seed}): {self.prompt}",
            )

    def _lay_out(self, plan: ScenePlan) -> tuple[Any, list[RoomFurniture]]:
        """The house shell of ``plan`` and every room furnished in it."""
        shell = build_shell(plan, self.seed, self.pick_material)
        for warning in shell.warnings:
            self.log.info("layout", f"warning: {warning}")
        context = RoomContext(
            walls=derive_walls(shell.rooms),
            doors=shell.doors,
            windows=shell.windows,
            wall_height=plan.wall_height,
            wall_thickness=SceneSpec.model_fields["wall_thickness"].default,
        )
        rooms = {r.id: r for r in shell.rooms}
        furnished = [
            furnish_room(
                plan_room,
                rooms[plan_room.id],
                context,
                self.assets[plan_room.id],
                self.library,
                self.seed,
                time_limit_s=self.options.layout_time_s,
                request=plan.prompt,
            )
            for plan_room in plan.rooms
        ]
        return shell, furnished

    def small_objects_stage(self) -> None:
        with self.log.stage("small_objects"):
            receptacles = [rec for r in self.furnished for rec in r.receptacles]
            small = drop_small_objects(
                self.scene,
                receptacles,
                self.library,
                self.retriever,
                self.seed,
                inside=self.options.inside,
            )
            self.scene = _mark_proxies(small.scene, self.library)
            self.log.info(
                "small_objects",
                f"{small.placed}/{small.requested} small object(s) dropped on "
                f"{len(receptacles)} receptacle(s)"
                + (f", {small.inside} of them inside furniture" if small.inside else ""),
            )
            for rec in small.receptacles:
                for failure in rec["failures"]:
                    self.log.info(
                        "small_objects",
                        f"{rec['receptacle']}: not placed: {failure['object']}: "
                        f"{failure['reason']}",
                    )
        self.small = small

    def validate_stage(self) -> None:
        from holomj.physics.scene_io import loaded_from_compiled
        from holomj.physics.settle import run_validation

        with self.log.stage("compile"):
            profile = check_profile(self.options.profile)
            self.compiled = compile_scene(self.scene, self.library, profile=profile)
        if self.options.robot is not None:
            from holomj.robots.attach import add_robot

            with self.log.stage("robot"):
                self.compiled = add_robot(
                    self.compiled, self.options.robot, stage_rng(self.seed, "robot")
                )
                robot = self.compiled.robot
                if robot is not None:
                    self.log.info(
                        "robot",
                        f"{robot.name} at ({robot.position[0]:.2f}, {robot.position[1]:.2f}), "
                        f"yaw {robot.yaw_deg:.1f} deg, in {robot.room}",
                    )
        with self.log.stage("validate"):
            # "free": the scene's own flags, where only bolted-down fixtures are static;
            # "static": the scene compiled again for validation with all furniture held still.
            validated = self.compiled
            mode = "as-is"
            if self.options.furniture == "static":
                from holomj.robots.attach import reattach_robot

                mode = "static"
                held = compile_scene(self.scene, self.library, profile=profile, furniture=mode)
                validated = reattach_robot(held, self.compiled)
            loaded = loaded_from_compiled(validated, self.library, self.out)
            report = run_validation(loaded, Thresholds(), mode, self.options.sleep).report
            self.log.info(
                "validate",
                f"{'ok' if report.ok else 'NOT ok'}: {report.counts['stable']}/"
                f"{report.counts['objects']} stable ({report.counts['dynamic']} simulated free, "
                f"{report.counts['static']} static), {report.counts['penetrations']} "
                f"penetration(s), max {report.max_penetration_m * 1000:.1f} mm, "
                f"{sum(report.warnings.values())} warning(s)",
            )
            if report.static_objects:
                self.log.info("validate", "static: " + ", ".join(report.static_objects))
            for obj in report.unstable():
                self.log.info("validate", f"unstable: {obj.name}: {'; '.join(obj.reasons)}")
        self.report = report

    def export_stage(self) -> None:
        self.record = self._record()
        with self.log.stage("export"):
            self.record["timings_s"] = dict(self.log.timings)
            write_scene_folder(
                self.compiled,
                self.out,
                overwrite=self.options.overwrite,
                extra_json={
                    PLAN_JSON: self.plan.model_dump(mode="json"),
                    REPORT_JSON: self.report.model_dump(mode="json"),
                    GENERATE_JSON: self.record,
                },
                extra_text={GENERATE_LOG: self.log.text()},
            )

    def _record(self) -> dict[str, Any]:
        furnished, small, scene = self.furnished, self.small, self.scene
        return {
            "prompt": self.prompt,
            "seed": self.seed,
            "planner": self.plan.planner,
            "library": str(self.library.root),
            "entrance": self.shell.entrance,
            "materials": self.shell.material_choices,
            "retrieval": [p for r in furnished for p in r.picks] + small.picks,
            "layout": {r.room_id: r.layout for r in furnished},
            "unplaced": [{**u, "room": r.room_id} for r in furnished for u in r.unplaced],
            "small_objects": small.receptacles,
            "counts": {
                "rooms": len(scene.rooms),
                "doors": len(scene.doors),
                "windows": len(scene.windows),
                "furniture": sum(len(r.objects) for r in furnished),
                "small_objects": small.placed,
                "objects": len(scene.objects),
            },
            "notes": [
                *self.plan.notes,
                *self.retriever.notes,
                *self.shell.warnings,
                *(c for r in furnished for c in r.changes),
            ],
            "plan_changes": [c for r in furnished for c in r.changes],
            "relations": [
                *(v for r in furnished for v in r.relations),
                *structural_verdicts(self.plan, scene, small.receptacles, self.library),
            ],
        }


def _mark_proxies(scene: SceneSpec, library: AssetLibrary) -> SceneSpec:
    """``scene`` with ``proxy: true`` on the objects whose asset is a proxy."""
    objects = [
        o.model_copy(update={"proxy": True})
        if o.asset in library and library.get(o.asset).meta.proxy
        else o
        for o in scene.objects
    ]
    return scene.model_copy(update={"objects": objects})


def _missing_defining(room: PlanRoom, done: RoomFurniture) -> list[str]:
    """The defining floor instances of ``room`` its furnishing could not place."""
    unplaced = {u["object"] for u in done.unplaced}
    return [
        instance
        for obj in room.objects
        if obj.defining and obj.placement == "floor"
        for instance in obj.instances()
        if instance in unplaced
    ]


def _why_grow(room: PlanRoom, done: RoomFurniture) -> str:
    """Why ``room`` should grow after its furnishing ``done`` (empty when it need not): its
    defining furniture did not fit, or its furniture cut off free floor a robot cannot reach."""
    if _missing_defining(room, done):
        return f"its {', '.join(sorted({o.name for o in room.objects if o.defining}))} fits"
    share = done.layout.get("reachable_share")
    if share is not None and share < REGROW_SHARE:
        return f"its free floor stays reachable ({share:.0%} was)"
    return ""


def _grow(plan: ScenePlan, why: dict[str, str]) -> tuple[ScenePlan, str]:
    """``plan`` with the rooms of ``why`` (room id -> the reason, in words) grown by ``GROWTH``
    in area, and what changed, in words."""
    rooms = [r for r in plan.rooms if r.id in why and r.area_m2 is not None]
    new_rooms = [
        r.model_copy(update={"area_m2": round(r.area_m2 * GROWTH, 1)})
        if r.id in why and r.area_m2 is not None
        else r
        for r in plan.rooms
    ]
    words = ", ".join(
        f"{r.id} from {r.area_m2:.1f} to {r.area_m2 * GROWTH:.1f} m² so that {why[r.id]}"
        for r in rooms
        if r.area_m2 is not None
    )
    return plan.model_copy(update={"rooms": new_rooms}), f"grew {words}"


def _render(
    out: Path, options: GenerateOptions, log: StageLog, compiled: CompiledScene
) -> dict[str, Any]:
    """Render views and the HTML report into ``out``; a failure is recorded, not raised.

    The outcome goes into the log and, as ``render`` (``ok``, ``error``, ``images``,
    ``report_html``), into ``out/generate.json`` (rewritten atomically), where the CLI reads it
    to report a failure and fail ``--strict``; it is also returned. Any exception counts as a
    failure (the scene is already written): ours with its one-line message, others with their
    type.
    """
    import json

    from holomj.jobs.render import render_folder, write_report_html

    outcome: dict[str, Any] = {"ok": False, "error": None, "images": 0, "report_html": None}
    try:
        with log.stage("render"):
            width, height = options.render_size
            summary = render_folder(out, width=width, height=height, compiled=compiled)
            outcome["images"] = sum(f.endswith(".png") for f in summary.files)
            page = write_report_html(out)
            outcome.update(ok=True, report_html=page.name)
            log.info("render", f"{outcome['images']} image(s), report {page.name}")
    except HolomjError as err:
        outcome["error"] = err.one_line()
    except Exception as err:  # a bug of ours must not lose the scene written before
        outcome["error"] = " ".join(f"{type(err).__name__}: {err}".split())
    if outcome["error"] is not None:
        log.info("render", f"render failed: {outcome['error']}")
    record_path = out / GENERATE_JSON
    try:
        record = json.loads(record_path.read_text(encoding="utf-8"))
        record["render"] = outcome
        write_file(record_path, dump_json(record))
    except (OSError, ValueError) as err:
        log.info("render", f"could not record the render outcome in {GENERATE_JSON}: {err}")
    return outcome


def _write_log(path: Path, log: StageLog) -> None:
    """Replace the log written with the export by the complete one (atomically)."""
    write_file(path, log.text())
