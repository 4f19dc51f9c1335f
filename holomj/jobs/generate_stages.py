"""The stages of ``generate`` (:func:`holomj.jobs.generate.generate_scene` calls them in a line):
each takes what it needs and returns what it made (small frozen records); only the log is
shared, and only to be written to."""

from __future__ import annotations

import contextlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.atomic import write_file
from holomj.compose.house import ComposedHouse, compose_house
from holomj.compose.house_shell import MaterialPicker
from holomj.compose.relation_report import structural_verdicts
from holomj.compose.room_assets import RoomAssets, retrieve_room
from holomj.compose.small_objects import choose_small_objects
from holomj.errors import HolomjError
from holomj.file_names import GENERATE_JSON, GENERATE_LOG, PLAN_JSON, REPORT_JSON
from holomj.jobs.folder import PreparedOutput, dump_json, write_scene_folder
from holomj.jobs.generate_options import CheckedRequest, GenerateOptions
from holomj.jobs.library import resolve_library
from holomj.jobs.plan import make_plan
from holomj.jobs.stage_log import StageLog
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.physics.small_object_drops import SmallObjects, drop_small_objects
from holomj.retrieval.chooser import AssetChooser
from holomj.seeds import stage_rng
from holomj.spec.plan import ScenePlan
from holomj.spec.report import StabilityReport, Thresholds
from holomj.spec.scene import SceneSpec


@dataclass(frozen=True)
class Retrieved:
    """The retrieval stage's output: the chooser (also for small objects; its ``notes``), the
    material picker and each room's assets (room id -> assets)."""

    chooser: AssetChooser
    notes: tuple[str, ...]
    pick_material: MaterialPicker
    assets: dict[str, RoomAssets]


@dataclass(frozen=True)
class Populated:
    """The scene with its small objects (proxies marked), what happened on each receptacle,
    and one record per small object picked."""

    scene: SceneSpec
    drops: SmallObjects
    picks: tuple[dict[str, Any], ...]


def open_library(options: GenerateOptions, log: StageLog) -> AssetLibrary:
    """The asset library of the run (the default one is built on first use)."""
    library = AssetLibrary.open(resolve_library(options.library))
    log.info(
        "setup",
        f"library {library.root} ({len(library.ids())} assets), seed {options.seed}",
    )
    return library


def plan_stage(
    prompt: str, options: GenerateOptions, library: AssetLibrary, log: StageLog
) -> ScenePlan:
    """The plan of ``prompt``."""
    with log.stage("plan"):
        plan = make_plan(prompt, options.plan_options(), library.categories(), log)
        furniture = sum(o.quantity for r in plan.rooms for o in r.objects)
        log.info(
            "plan",
            f"{plan.planner} plan: {plan.scene_type} "
            f"({plan.scene_type_match or 'direct'}), {len(plan.rooms)} room(s), "
            f"{furniture} furniture item(s)",
        )
        for note in plan.notes:
            log.info("plan", f"note: {note}")
    return plan


def retrieve_stage(
    plan: ScenePlan, library: AssetLibrary, options: GenerateOptions, log: StageLog
) -> Retrieved:
    """An asset for every planned floor, wall and ceiling instance, and the material picker."""
    from holomj.jobs.synthesis import LibrarySynthesiser
    from holomj.retrieval.assets import retriever_for
    from holomj.retrieval.materials import material_picker
    from holomj.retrieval.text import text_encoder

    with log.stage("retrieve"):
        encoder = text_encoder(options.text_model)
        # Assets the library lacks (a category, a colour, a shape) are made on demand into
        # it, or into $HOLOMJ_HOME/synthesised when it is read-only; see
        # holomj.jobs.synthesis.
        retriever = retriever_for(
            library,
            clip_weights=options.clip_weights,
            clip_model=options.clip_model,
            encoder=encoder,
            synthesiser=LibrarySynthesiser(library),
        )
        pick_material = material_picker(encoder=encoder, materials=options.materials)
        assets = {r.id: retrieve_room(r, library, retriever, options.seed) for r in plan.rooms}
        for note in retriever.notes:
            log.info("retrieve", note)
        picked = sum(len(a.floor) + len(a.wall) for a in assets.values())
        log.info("retrieve", f"{picked} asset(s) chosen")
    return Retrieved(retriever, tuple(retriever.notes), pick_material, assets)


def compose_stage(
    prompt: str,
    plan: ScenePlan,
    retrieved: Retrieved,
    library: AssetLibrary,
    options: GenerateOptions,
    log: StageLog,
) -> ComposedHouse:
    """The house laid out and furnished (:func:`holomj.compose.house.compose_house`)."""
    with log.stage("layout"):
        return compose_house(
            prompt,
            plan,
            retrieved.assets,
            library,
            options.seed,
            retrieved.pick_material,
            layout_time_s=options.layout_time,
            note=lambda line: log.info("layout", line),
        )


def small_objects_stage(
    house: ComposedHouse,
    retrieved: Retrieved,
    library: AssetLibrary,
    options: GenerateOptions,
    log: StageLog,
) -> Populated:
    """Small objects chosen for every receptacle, then dropped onto (and into) it."""
    with log.stage("small_objects"):
        receptacles = [rec for r in house.furnished for rec in r.receptacles]
        choices = choose_small_objects(
            house.scene,
            receptacles,
            library,
            retrieved.chooser,
            options.seed,
            inside=options.inside,
        )
        small = drop_small_objects(house.scene, choices.drops, library)
        log.info(
            "small_objects",
            f"{small.placed}/{small.requested} small object(s) dropped on "
            f"{len(receptacles)} receptacle(s)"
            + (f", {small.inside} of them inside furniture" if small.inside else ""),
        )
        for rec in small.receptacles:
            for failure in rec["failures"]:
                log.info(
                    "small_objects",
                    f"{rec['receptacle']}: not placed: {failure['object']}: {failure['reason']}",
                )
    return Populated(mark_proxies(small.scene, library), small, choices.picks)


def mark_proxies(scene: SceneSpec, library: AssetLibrary) -> SceneSpec:
    """``scene`` with ``proxy: true`` on the objects whose asset is a proxy."""
    objects = [
        o.model_copy(update={"proxy": True})
        if o.asset in library and library.get(o.asset).meta.proxy
        else o
        for o in scene.objects
    ]
    return scene.model_copy(update={"objects": objects})


def compile_stage(
    scene: SceneSpec, library: AssetLibrary, checked: CheckedRequest, seed: int, log: StageLog
) -> CompiledScene:
    """The scene compiled (once), with the robot when one was asked for."""
    with log.stage("compile"):
        compiled = compile_scene(scene, library, profile=checked.profile)
    if checked.robot is None:
        return compiled
    from holomj.robots.attach import add_robot

    with log.stage("robot"):
        compiled = add_robot(compiled, checked.robot, stage_rng(seed, "robot"))
        robot = compiled.robot
        if robot is not None:
            log.info(
                "robot",
                f"{robot.name} at ({robot.position[0]:.2f}, {robot.position[1]:.2f}), "
                f"yaw {robot.yaw_deg:.1f} deg, in {robot.room}",
            )
    return compiled


def validate_stage(
    compiled: CompiledScene,
    library: AssetLibrary,
    checked: CheckedRequest,
    options: GenerateOptions,
    log: StageLog,
) -> StabilityReport:
    """The validation report of the compiled scene. "free": the scene's own flags, where only
    bolted-down fixtures are static; "static": the scene compiled again for validation with all
    furniture held still."""
    from holomj.physics.scene_io import loaded_from_compiled
    from holomj.physics.settle import run_validation

    with log.stage("validate"):
        validated, mode = compiled, "as-is"
        if options.furniture == "static":
            from holomj.robots.attach import reattach_robot

            mode = "static"
            held = compile_scene(
                compiled.scene, library, profile=checked.profile, furniture="static"
            )
            validated = reattach_robot(held, compiled)
        loaded = loaded_from_compiled(validated, library, checked.out.path)
        report = run_validation(loaded, Thresholds(), mode, options.sleep).report
        log.info(
            "validate",
            f"{'ok' if report.ok else 'NOT ok'}: {report.counts['stable']}/"
            f"{report.counts['objects']} stable ({report.counts['dynamic']} simulated free, "
            f"{report.counts['static']} static), {report.counts['penetrations']} "
            f"penetration(s), max {report.max_penetration_m * 1000:.1f} mm, "
            f"{sum(report.warnings.values())} warning(s)",
        )
        if report.static_objects:
            log.info("validate", "static: " + ", ".join(report.static_objects))
        for obj in report.unstable():
            log.info("validate", f"unstable: {obj.name}: {'; '.join(obj.reasons)}")
    return report


def generate_record(
    prompt: str,
    seed: int,
    library: AssetLibrary,
    retrieved: Retrieved,
    house: ComposedHouse,
    populated: Populated,
) -> dict[str, Any]:
    """``generate.json`` without its timings and render outcome: what every stage chose and
    why."""
    furnished, small, scene = house.furnished, populated.drops, populated.scene
    changes = [c for r in furnished for c in r.changes]
    return {
        "prompt": prompt,
        "seed": seed,
        "planner": house.plan.planner,
        "library": str(library.root),
        "entrance": house.shell.entrance,
        "materials": house.shell.material_choices,
        "retrieval": [p for r in furnished for p in r.picks] + list(populated.picks),
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
        "notes": [*house.plan.notes, *retrieved.notes, *house.shell.warnings, *changes],
        "plan_changes": changes,
        "relations": [
            *(v for r in furnished for v in r.relations),
            *structural_verdicts(house.plan, scene, small.receptacles, library),
        ],
    }


def export_stage(
    out: PreparedOutput,
    compiled: CompiledScene,
    plan: ScenePlan,
    report: StabilityReport,
    record: dict[str, Any],
    options: GenerateOptions,
    log: StageLog,
) -> dict[str, Any]:
    """Write the folder in one atomic step: the scene, ``plan.json``, ``report.json``, then (on
    the filled temporary folder) the renders and ``report.html`` when asked, and last
    ``generate.json`` (``record`` with the timings and the render's outcome) and
    ``generate.log``. Returns the complete record."""
    final: dict[str, Any] = {}

    with contextlib.ExitStack() as exporting:
        exporting.enter_context(log.stage("export"))

        def finish(tmp: Path) -> None:
            exporting.close()  # the scene is written: the export stage ends, the render starts
            final.update(record)
            if options.render:
                final["render"] = _render(tmp, out.path, compiled, options, log)
            final["timings_s"] = dict(log.timings)
            write_file(tmp / GENERATE_JSON, dump_json(final))
            write_file(tmp / GENERATE_LOG, log.text())

        write_scene_folder(
            compiled,
            out,
            extra_json={
                PLAN_JSON: plan.model_dump(mode="json"),
                REPORT_JSON: report.model_dump(mode="json"),
            },
            finish=finish,
        )
    return final


def _render(
    folder: Path,
    final_path: Path,
    compiled: CompiledScene,
    options: GenerateOptions,
    log: StageLog,
) -> dict[str, Any]:
    """Render views and the HTML report into ``folder`` (the temporary folder that becomes
    ``final_path``) from ``compiled``; a failure is
    recorded, not raised: the outcome (``ok``, ``error``, ``images``, ``report_html``) goes into
    the log and ``generate.json`` (``render``), where the CLI reads it to report a failure and
    fail ``--strict``. Any exception counts as a failure (the scene is written all the same):
    ours with its one-line message, others with their type."""
    from holomj.jobs.render import render_folder, write_report_html

    outcome: dict[str, Any] = {"ok": False, "error": None, "images": 0, "report_html": None}
    try:
        with log.stage("render"):
            summary = render_folder(
                folder,
                width=options.width,
                height=options.height,
                compiled=compiled,
                recorded_out=final_path,
            )
            outcome["images"] = sum(f.endswith(".png") for f in summary.files)
            page = write_report_html(folder, compiled=compiled)
            outcome.update(ok=True, report_html=page.name)
            log.info("render", f"{outcome['images']} image(s), report {page.name}")
    except HolomjError as err:
        outcome["error"] = err.one_line()
    except Exception as err:  # a bug of ours must not lose the scene
        outcome["error"] = " ".join(f"{type(err).__name__}: {err}".split())
    if outcome["error"] is not None:
        log.info("render", f"render failed: {outcome['error']}")
    return outcome
