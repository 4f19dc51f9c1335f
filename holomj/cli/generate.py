"""``holomj generate`` (prompt -> validated scene folder) and ``holomj plan`` (prompt -> plan); the
jobs: :mod:`holomj.jobs.generate` and :mod:`holomj.jobs.plan`.

Exit codes: 0 when the scene was written (``--strict``: and validated ok and, unless
``--no-render``, rendered, else 1), 2 for bad input (empty prompt, existing OUT without
``--overwrite``, bad options), 1 for a failure of ours. A render failure leaves the scene written;
it is printed as one line on stderr (``render failed: ...``) and recorded in ``generate.json``
(``render``) and ``generate.log``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli.options import (
    FurnitureOption,
    JsonOption,
    LibraryOption,
    LlmConfigOption,
    LlmKeyOption,
    LlmModelOption,
    LlmUrlOption,
    MaterialsOption,
    OutFileOption,
    OutFolderOption,
    OverwriteOption,
    PlannerOption,
    ProfileOption,
    PromptArg,
    QuietOption,
    RenderHeightOption,
    RenderOption,
    RenderWidthOption,
    RobotOption,
    SeedOption,
    StrictOption,
    TextModelOption,
)
from holomj.cli.output import emit_json, err_console, guard, out_console, spinner


def generate_command(
    prompt: PromptArg,
    out: OutFolderOption,
    seed: SeedOption = 0,
    planner: PlannerOption = "offline",
    library: LibraryOption = None,
    overwrite: OverwriteOption = False,
    render: RenderOption = True,
    width: RenderWidthOption = 640,
    height: RenderHeightOption = 480,
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
    materials: MaterialsOption = None,
    llm_base_url: LlmUrlOption = None,
    llm_model: LlmModelOption = None,
    llm_api_key: LlmKeyOption = None,
    llm_config: LlmConfigOption = None,
    layout_time: Annotated[
        float,
        typer.Option("--layout-time", min=0.1, max=120.0, help="Layout solver seconds per room."),
    ] = 1.0,
    strict: StrictOption = False,
    furniture: FurnitureOption = "free",
    robot: RobotOption = None,
    profile: ProfileOption = "default",
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Build a physically valid scene from a text prompt: plan, retrieve, lay out, drop small
    objects, validate, export (and render).

    --strict: exit 1 when the scene does not validate ok or the render fails.
    """
    from holomj.jobs.generate import GenerateOptions, generate_scene

    options = GenerateOptions(
        seed=seed,
        planner=planner,
        library=library,
        overwrite=overwrite,
        render=render,
        width=width,
        height=height,
        furniture=furniture,
        robot=robot,
        profile=profile,
        text_model=text_model,
        clip_weights=clip_weights,
        clip_model=clip_model,
        materials=materials,
        llm_base_url=llm_base_url,
        llm_model=llm_model,
        llm_api_key=llm_api_key,
        llm_config=llm_config,
        layout_time=layout_time,
    )
    show = not (quiet or as_json)
    with spinner("generating", show=show) as status:

        def listener(stage: str, message: str) -> None:
            if show:
                status.update(f"{stage}: {message}"[:120])

        result = guard(lambda: generate_scene(prompt, out, options, listener=listener))
    failure = result.render_error
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
    out: OutFileOption = None,
    seed: SeedOption = 0,
    planner: PlannerOption = "offline",
    text_model: TextModelOption = None,
    llm_base_url: LlmUrlOption = None,
    llm_model: LlmModelOption = None,
    llm_api_key: LlmKeyOption = None,
    llm_config: LlmConfigOption = None,
) -> None:
    """Plan a scene from a prompt without building it: print (or write) the ScenePlan JSON."""
    from holomj.jobs.folder import write_json_file
    from holomj.jobs.plan import PlanOptions, plan_scene

    options = PlanOptions(
        seed=seed,
        planner=planner,
        text_model=text_model,
        llm_base_url=llm_base_url,
        llm_model=llm_model,
        llm_api_key=llm_api_key,
        llm_config=llm_config,
    )

    def listener(stage: str, message: str) -> None:
        err_console.print(f"{stage}: {message}", markup=False)

    plan = guard(lambda: plan_scene(prompt, options, listener=listener))
    target = Path("-") if out is None else out
    guard(lambda: write_json_file(target, plan.model_dump(mode="json")))
