"""``holomj generate`` (prompt -> validated scene folder) and ``holomj plan`` (prompt -> plan).

Exit codes: 0 when the scene was written (``--strict``: and validated ok and, unless
``--no-render``, rendered, else 1), 2 for bad input (empty prompt, existing OUT without
``--overwrite``, bad options), 1 for a failure of ours. A render failure leaves the scene written;
it is printed as one line on stderr (``render failed: ...``) and recorded in ``generate.json``
(``render``) and ``generate.log``.
"""

from __future__ import annotations

import contextlib
import json
from pathlib import Path
from typing import Annotated, Any

import typer

from holomj.cli_common import (
    LibraryOption,
    emit_json,
    err_console,
    guard,
    out_console,
    write_text,
)
from holomj.cli_robot import ProfileOption, RobotOption
from holomj.errors import InputError

PLANNERS = ("offline", "llm")

PromptArg = Annotated[str, typer.Argument(metavar="PROMPT", help="What to build, in words.")]
SeedOption = Annotated[int, typer.Option("--seed", min=0, max=2**32 - 1, help="Random seed.")]
PlannerOption = Annotated[
    str,
    typer.Option(
        "--planner",
        help="offline (knowledge base, no network) or llm (OpenAI-compatible endpoint from "
        "--llm-* options, HOLOMJ_LLM_* variables or $HOLOMJ_HOME/config.toml).",
    ),
]
TextModelOption = Annotated[
    Path | None,
    typer.Option(
        "--text-model",
        help="Local sentence-transformers model folder (default: the shipped all-MiniLM-L6-v2, "
        "or $HOLOMJ_TEXT_MODEL).",
    ),
]
LlmUrlOption = Annotated[
    str | None, typer.Option("--llm-base-url", help="e.g. http://localhost:11434/v1")
]
LlmModelOption = Annotated[str | None, typer.Option("--llm-model", help="Model name.")]
LlmKeyOption = Annotated[
    str | None, typer.Option("--llm-api-key", help="API key (or HOLOMJ_LLM_API_KEY).")
]
LlmConfigOption = Annotated[
    Path | None, typer.Option("--llm-config", help="TOML file with an [llm] table.")
]


def render_failure(out: Path) -> str | None:
    """Why the render stage of the generate run that wrote ``out`` failed, or None when it
    succeeded (read from ``generate.json``'s ``render`` record, which the stage writes)."""
    from holomj.jobs.generate import GENERATE_JSON

    path = Path(out) / GENERATE_JSON
    try:
        outcome: Any = json.loads(path.read_text(encoding="utf-8")).get("render")
    except (OSError, ValueError, AttributeError) as err:
        return f"cannot read the render outcome from {path}: {err}"
    if not isinstance(outcome, dict):
        return f"{path} holds no render outcome"
    if outcome.get("ok") is True:
        return None
    return str(outcome.get("error") or "unknown error")


def _check_furniture(value: str) -> None:
    if value not in ("free", "static"):
        raise InputError(f"unknown value {value!r}", where="--furniture", fix="use free or static")


def _check_planner(planner: str) -> None:
    if planner not in PLANNERS:
        raise InputError(
            f"unknown planner {planner!r}", where="--planner", fix="use offline or llm"
        )


def generate_command(
    prompt: PromptArg,
    out: Annotated[Path, typer.Option("--out", "-o", help="Output folder to create.")],
    seed: SeedOption = 0,
    planner: PlannerOption = "offline",
    library: LibraryOption = None,
    overwrite: Annotated[
        bool, typer.Option("--overwrite", help="Replace OUT if it exists.")
    ] = False,
    render: Annotated[
        bool, typer.Option("--render/--no-render", help="Render views and report.html.")
    ] = True,
    width: Annotated[int, typer.Option("--width", min=32, max=4096, help="Render width.")] = 640,
    height: Annotated[int, typer.Option("--height", min=32, max=4096, help="Render height.")] = 480,
    text_model: TextModelOption = None,
    clip_weights: Annotated[
        Path | None,
        typer.Option(
            "--clip-weights",
            help="Local open-clip weights for the visual retrieval term (needs the clip extra: "
            "pip install 'holomj\\[clip]'; default $HOLOMJ_CLIP_WEIGHTS; absent: the term is "
            "left out).",
        ),
    ] = None,
    clip_model: Annotated[
        str | None, typer.Option("--clip-model", help="open-clip architecture (ViT-B-32).")
    ] = None,
    materials: Annotated[
        Path | None,
        typer.Option("--materials", help="Material library folder (holomj materials import)."),
    ] = None,
    llm_base_url: LlmUrlOption = None,
    llm_model: LlmModelOption = None,
    llm_api_key: LlmKeyOption = None,
    llm_config: LlmConfigOption = None,
    layout_time: Annotated[
        float,
        typer.Option("--layout-time", min=0.1, max=120.0, help="Layout solver seconds per room."),
    ] = 1.0,
    strict: Annotated[
        bool,
        typer.Option(
            "--strict", help="Exit 1 when the scene does not validate ok or the render fails."
        ),
    ] = False,
    furniture: Annotated[
        str,
        typer.Option(
            "--furniture",
            help="How validation simulates furniture: free (all but the bolted-down fixtures: "
            "counters, base cabinets, cookers, sanitary ware; the report lists them) or static.",
        ),
    ] = "free",
    robot: RobotOption = None,
    profile: ProfileOption = "default",
    as_json: Annotated[bool, typer.Option("--json", help="Print a JSON summary.")] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing on success.")] = False,
) -> None:
    """Build a physically valid scene from a text prompt: plan, retrieve, lay out, drop small
    objects, validate, export (and render)."""
    from holomj.cli_assets import resolve_library
    from holomj.jobs.generate import GenerateOptions, generate_scene

    guard(lambda: _check_planner(planner))
    guard(lambda: _check_furniture(furniture))
    library_root = resolve_library(library)
    options = GenerateOptions(
        library=library_root,
        seed=seed,
        planner=planner,  # type: ignore[arg-type]
        overwrite=overwrite,
        render=render,
        render_size=(width, height),
        text_model=text_model,
        clip_weights=clip_weights,
        clip_model=clip_model,
        materials=materials,
        llm_base_url=llm_base_url,
        llm_model=llm_model,
        llm_api_key=llm_api_key,
        llm_config=llm_config,
        layout_time_s=layout_time,
        furniture=furniture,  # type: ignore[arg-type]
        robot=robot,
        profile=profile,
    )
    show = not (quiet or as_json)
    status = err_console.status("generating", spinner="dots") if show else None
    with status if status is not None else contextlib.nullcontext():

        def listener(stage: str, message: str) -> None:
            if status is not None:
                status.update(f"{stage}: {message}"[:120])

        result = guard(lambda: generate_scene(prompt, out, options, listener=listener))
    failure = render_failure(out) if render else None
    summary = result.summary()
    summary["render"] = None if not render else {"ok": failure is None, "error": failure}
    if as_json:
        emit_json(summary)
    elif not quiet:
        counts = summary["objects"]
        verdict = "[bold green]ok[/]" if result.report.ok else "[bold red]NOT ok[/]"
        out_console.print(
            f"[bold green]generated[/] {result.plan.scene_type} ({result.plan.planner} plan) "
            f"-> {out}/scene.xml"
        )
        out_console.print(
            f"  {counts['rooms']} rooms, {counts['doors']} doors, {counts['windows']} windows, "
            f"{counts['furniture']} furniture, {counts['small_objects']} small objects; "
            f"validation {verdict}"
        )
        timing = ", ".join(f"{k} {v:.1f} s" for k, v in result.timings.items())
        out_console.print(f"  {timing}")
        for note in summary["notes"]:
            out_console.print(f"  note: {note}", markup=False)
    if failure is not None:  # even with --quiet or --json: it is not a success
        err_console.print(f"render failed: {' '.join(failure.split())}", markup=False)
    if strict and (not result.report.ok or failure is not None):
        raise typer.Exit(code=1)


def plan_command(
    prompt: PromptArg,
    out: Annotated[
        Path | None, typer.Option("--out", "-o", help="Write the plan JSON here.")
    ] = None,
    seed: SeedOption = 0,
    planner: PlannerOption = "offline",
    text_model: TextModelOption = None,
    llm_base_url: LlmUrlOption = None,
    llm_model: LlmModelOption = None,
    llm_api_key: LlmKeyOption = None,
    llm_config: LlmConfigOption = None,
) -> None:
    """Plan a scene from a prompt without building it: print (or write) the ScenePlan JSON."""
    from holomj.jobs.folder import dump_json
    from holomj.jobs.generate import PlanOptions, make_plan
    from holomj.jobs.stage_log import StageLog
    from holomj.library.store import AssetLibrary

    guard(lambda: _check_planner(planner))
    options = PlanOptions(
        seed=seed,
        planner=planner,  # type: ignore[arg-type]
        text_model=text_model,
        llm_base_url=llm_base_url,
        llm_model=llm_model,
        llm_api_key=llm_api_key,
        llm_config=llm_config,
    )
    categories: list[str] = []
    if planner == "llm":
        from holomj.cli_assets import resolve_library

        categories = AssetLibrary.open(resolve_library(None)).categories()
    log = StageLog(lambda stage, message: err_console.print(f"{stage}: {message}", markup=False))
    plan = guard(lambda: make_plan(prompt, options, categories, log))
    text = dump_json(plan.model_dump(mode="json"))
    if out is None:
        typer.echo(text, nl=False)
    else:
        guard(lambda: write_text(out, text))
