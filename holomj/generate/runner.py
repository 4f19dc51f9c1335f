"""``generate``: a prompt in, a validated scene folder out (the stage runner).

Stages, each timed in the log: plan (offline knowledge base, or an LLM with the offline planner
as fallback) -> retrieve + layout per room (floor plan, doors, windows, materials, furniture,
wall objects) -> small objects (spawn-and-drop) -> compile -> validate -> export (atomic) ->
render (optional, after the export; a failed render is logged and leaves the scene intact).

``OUT`` receives ``scene.xml``, ``assets/``, ``scene.json``, ``plan.json``, ``report.json`` (the
validation report, as ``holomj validate`` writes it), ``generate.json`` (what every stage chose
and why, timings) and ``generate.log`` (one line per event).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from holomj.errors import HolomjError, InputError
from holomj.export.writer import export_scene, prepare_output
from holomj.generate.furnish import RoomContext, furnish_room
from holomj.generate.house import build_shell
from holomj.generate.small_objects import drop_small_objects
from holomj.generate.stage_log import Listener, StageLog
from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import compile_scene
from holomj.spec.materials import BUILTIN_MATERIALS
from holomj.spec.plan import ScenePlan
from holomj.spec.report import StabilityReport, Thresholds
from holomj.spec.scene import SceneSpec

PLAN_JSON = "plan.json"
REPORT_JSON = "report.json"
GENERATE_JSON = "generate.json"
GENERATE_LOG = "generate.log"
MAX_PROMPT_CHARS = 2000


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


@dataclass
class GenerateResult:
    """What ``generate`` made: the folder, the plan, the validation report, the record."""

    out: Path
    plan: ScenePlan
    report: StabilityReport
    record: dict[str, Any]
    timings: dict[str, float] = field(default_factory=dict)

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


def make_plan(
    prompt: str, options: GenerateOptions, categories: list[str], log: StageLog
) -> ScenePlan:
    """The plan of ``prompt``: offline, or from the LLM with the offline planner as fallback."""
    from holomj.plan.offline import plan_offline
    from holomj.retrieval.text import text_encoder

    def offline(text: str, seed: int) -> ScenePlan:
        return plan_offline(text, seed, encoder=text_encoder(options.text_model))

    if options.planner == "offline":
        return offline(prompt, options.seed)
    from holomj.plan.llm import plan_llm
    from holomj.plan.llm_config import load_llm_config

    config = load_llm_config(
        base_url=options.llm_base_url,
        model=options.llm_model,
        api_key=options.llm_api_key,
        config_file=options.llm_config,
    )
    return plan_llm(
        prompt,
        options.seed,
        config=config,
        fallback=offline,
        categories=categories,
        log=lambda line: log.info("plan", line),
    )


def generate_scene(
    prompt: str,
    out: Path,
    options: GenerateOptions,
    *,
    listener: Listener | None = None,
) -> GenerateResult:
    """Run every stage for ``prompt`` and write ``out`` (see the module docstring)."""
    from holomj.physics.scene_io import loaded_from_compiled
    from holomj.physics.settle import run_validation
    from holomj.retrieval.assets import retriever_for
    from holomj.retrieval.materials import material_picker
    from holomj.retrieval.text import text_encoder

    if not prompt.strip():
        raise InputError("the prompt is empty", where="PROMPT", fix='e.g. "a small kitchen"')
    if len(prompt) > MAX_PROMPT_CHARS:
        raise InputError(
            f"the prompt has {len(prompt)} characters, more than {MAX_PROMPT_CHARS}",
            where="PROMPT",
        )
    out = Path(out)
    prepare_output(out, options.overwrite)
    log = StageLog(listener)
    seed = options.seed
    library = AssetLibrary.open(options.library)
    log.info("setup", f"library {library.root} ({len(library.ids())} assets), seed {seed}")

    with log.stage("plan"):
        plan = make_plan(prompt, options, library.categories(), log)
        log.info(
            "plan",
            f"{plan.planner} plan: {plan.scene_type} ({plan.scene_type_match or 'direct'}), "
            f"{len(plan.rooms)} room(s), "
            f"{sum(o.quantity for r in plan.rooms for o in r.objects)} furniture item(s)",
        )
        for note in plan.notes:
            log.info("plan", f"note: {note}")

    with log.stage("retrieve"):
        encoder = text_encoder(options.text_model)
        retriever = retriever_for(
            library,
            clip_weights=options.clip_weights,
            clip_model=options.clip_model,
            encoder=encoder,
        )
        pick_material = material_picker(encoder=encoder, materials=options.materials)
        for note in retriever.notes:
            log.info("retrieve", note)

    with log.stage("layout"):
        shell = build_shell(plan, seed, pick_material)
        for warning in shell.warnings:
            log.info("layout", f"warning: {warning}")
        context = RoomContext(
            walls=SceneSpec(rooms=shell.rooms).walls,
            doors=shell.doors,
            windows=shell.windows,
            wall_height=plan.wall_height,
            wall_thickness=SceneSpec.model_fields["wall_thickness"].default,
        )
        rooms_done = []
        for plan_room in plan.rooms:
            room = next(r for r in shell.rooms if r.id == plan_room.id)
            furnished = furnish_room(
                plan_room,
                room,
                context,
                library,
                retriever,
                seed,
                time_limit_s=options.layout_time_s,
            )
            rooms_done.append(furnished)
            lay = furnished.layout
            log.info(
                "layout",
                f"{room.id}: {len(furnished.objects)} object(s) placed, "
                f"{len(furnished.unplaced)} not, constraints "
                f"{lay.get('constraints_satisfied', 0)}/{lay.get('constraints_total', 0)} "
                f"({lay.get('solver', '-')}, {lay.get('seconds', 0):.2f} s)",
            )
            for item in furnished.unplaced:
                log.info("layout", f"{room.id}: not placed: {item['object']}: {item['reason']}")
        scene = SceneSpec(
            name=scene_name(prompt),
            wall_height=plan.wall_height,
            rooms=shell.rooms,
            doors=shell.doors,
            windows=shell.windows,
            objects=[o for r in rooms_done for o in r.objects],
            materials={n: m for n, m in shell.materials.items() if n not in BUILTIN_MATERIALS},
            source=f"holomj generate (seed {seed}): {prompt}",
        )

    with log.stage("small_objects"):
        receptacles = [rec for r in rooms_done for rec in r.receptacles]
        small = drop_small_objects(scene, receptacles, library, retriever, seed)
        scene = small.scene
        log.info(
            "small_objects",
            f"{small.placed}/{small.requested} small object(s) dropped on "
            f"{len(receptacles)} receptacle(s)",
        )
        for rec in small.receptacles:
            for failure in rec["failures"]:
                log.info(
                    "small_objects",
                    f"{rec['receptacle']}: not placed: {failure['object']}: {failure['reason']}",
                )

    with log.stage("compile"):
        compiled = compile_scene(scene, library)

    with log.stage("validate"):
        loaded = loaded_from_compiled(compiled, library, out)
        report = run_validation(loaded, Thresholds(), "as-is", options.sleep).report
        log.info(
            "validate",
            f"{'ok' if report.ok else 'NOT ok'}: {report.counts['stable']}/"
            f"{report.counts['objects']} stable, {report.counts['penetrations']} "
            f"penetration(s), max {report.max_penetration_m * 1000:.1f} mm, "
            f"{sum(report.warnings.values())} warning(s)",
        )

    notes = [*plan.notes, *retriever.notes, *shell.warnings]
    record = {
        "prompt": prompt,
        "seed": seed,
        "planner": plan.planner,
        "library": str(library.root),
        "entrance": shell.entrance,
        "materials": shell.material_choices,
        "retrieval": [p for r in rooms_done for p in r.picks] + small.picks,
        "layout": {r.room_id: r.layout for r in rooms_done},
        "unplaced": [{**u, "room": r.room_id} for r in rooms_done for u in r.unplaced],
        "small_objects": small.receptacles,
        "counts": {
            "rooms": len(scene.rooms),
            "doors": len(scene.doors),
            "windows": len(scene.windows),
            "furniture": sum(len(r.objects) for r in rooms_done),
            "small_objects": small.placed,
            "objects": len(scene.objects),
        },
        "notes": notes,
    }
    with log.stage("export"):
        record["timings_s"] = dict(log.timings)
        export_scene(
            compiled,
            out,
            overwrite=options.overwrite,
            extra_json={
                PLAN_JSON: plan.model_dump(mode="json"),
                REPORT_JSON: report.model_dump(mode="json"),
                GENERATE_JSON: record,
            },
            extra_text={GENERATE_LOG: log.text()},
        )
    if options.render:
        _render(out, options, log)
    record["timings_s"] = dict(log.timings)
    return GenerateResult(out, plan, report, record, dict(log.timings))


def _render(out: Path, options: GenerateOptions, log: StageLog) -> None:
    """Render views and the HTML report into ``out``; a failure is logged, not raised."""
    from holomj.render.folder import render_folder, write_report_html

    try:
        with log.stage("render"):
            width, height = options.render_size
            summary = render_folder(out, width=width, height=height)
            page = write_report_html(out)
            log.info("render", f"{len(summary.files)} image(s), report {page.name}")
    except HolomjError as err:
        log.info("render", f"skipped: {err.one_line()}")
    (out / GENERATE_LOG).write_text(log.text(), encoding="utf-8")
