"""``holomj refine OUT --instruction TEXT [--rounds N] [--planner offline|llm] [-o NEW]``: make a
scene better round by round (the job: :mod:`holomj.jobs.refine`).

Each round renders small views, asks the planner for edit operations (offline: the edits that
fix what ``holomj eval`` finds; llm: a vision-language model shown the views, the scene summary
and the operations' schema, its answers checked as data), applies them to a copy, validates and
scores it (the mean of the eval scores and of the instruction's checks) and keeps the copy only
when it validates and the score does not fall. ``refine.json`` in the written folder logs every
round. The result goes back into OUT, or into NEW (``-o``), atomically.

Exit codes: 0 when the instruction's checks all hold and the scene validates, 1 when not (the
best scene found and refine.json are written all the same), 2 for bad input.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from holomj.cli.options import (
    FolderArg,
    LibraryOption,
    LlmConfigOption,
    LlmKeyOption,
    LlmModelOption,
    LlmUrlOption,
    OverwriteOption,
    PlannerOption,
    QuietOption,
    SeedOption,
    llm_settings,
)
from holomj.cli.output import emit_json, err_console, guard, library_root, out_console

if TYPE_CHECKING:
    from holomj.jobs.refine import RefineResult


InstructionOption = Annotated[
    str,
    typer.Option(
        "--instruction",
        "-i",
        help="What to change, in words: 'add a reading corner with an armchair and a "
        "floor lamp by the window'.",
    ),
]
RoundsOption = Annotated[int, typer.Option("--rounds", min=1, max=20, help="At most this many.")]
NewFolderOption = Annotated[
    Path | None,
    typer.Option(
        "--out", "-o", metavar="NEW", help="Write the refined scene here (default: into OUT)."
    ),
]
MaxOpsOption = Annotated[
    int, typer.Option("--max-ops", min=1, max=50, help="Edit operations per round.")
]
ImagesOption = Annotated[
    bool,
    typer.Option(
        "--images/--no-images",
        help="Send the rendered views to the LLM (--no-images: text only; also "
        "HOLOMJ_LLM_IMAGES=0).",
    ),
]
RenderViewsOption = Annotated[
    bool, typer.Option("--render/--no-render", help="Render views each round.")
]
RefineJsonOption = Annotated[bool, typer.Option("--json", help="Print refine.json on stdout.")]


def refine_command(
    scene: FolderArg,
    instruction: InstructionOption,
    rounds: RoundsOption = 3,
    planner: PlannerOption = "offline",
    out: NewFolderOption = None,
    overwrite: OverwriteOption = False,
    seed: SeedOption = 0,
    library: LibraryOption = None,
    max_ops: MaxOpsOption = 8,
    images: ImagesOption = True,
    render: RenderViewsOption = True,
    llm_base_url: LlmUrlOption = None,
    llm_model: LlmModelOption = None,
    llm_api_key: LlmKeyOption = None,
    llm_config: LlmConfigOption = None,
    as_json: RefineJsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Refine a scene by an instruction: render, plan edits, apply, score, keep what helps."""
    from holomj.jobs.folder import require_scene_folder
    from holomj.jobs.refine import refine

    guard(lambda: require_scene_folder(scene, "holomj generate' or 'holomj compile"))
    library_path = library_root(library)
    settings = llm_settings(llm_base_url, llm_model, llm_api_key, llm_config)
    verbose = not quiet and not as_json

    def say(line: str) -> None:
        if verbose:
            err_console.print(line, markup=False)

    result = guard(
        lambda: refine(
            scene,
            instruction,
            rounds=rounds,
            planner=planner,  # type: ignore[arg-type]  # refine checks the name and says so
            out=out,
            overwrite=overwrite,
            seed=seed,
            library_path=library_path,
            llm_config=settings if planner == "llm" else None,
            images=None if images else False,
            max_ops=max_ops,
            render=render,
            log=say,
        )
    )
    if as_json:
        emit_json(result.record)
    elif not quiet:
        _print_result(result)
    if not result.ok:
        raise typer.Exit(code=1)


def _print_result(result: RefineResult) -> None:
    """The scores before and after, the rounds kept and the checks not met."""
    from holomj.jobs.refine import REFINE_JSON

    colour = "green" if result.ok else "yellow"
    met = sum(1 for c in result.checks if c["held"])
    out_console.print(
        f"[bold {colour}]refined[/] -> {result.folder}: score {result.score_before:.3f} -> "
        f"{result.score_after:.3f}, {result.kept}/{len(result.rounds)} round(s) kept, "
        f"instruction {met}/{len(result.checks)} checks met, "
        f"{'validated' if result.valid else 'NOT validated'} "
        f"({result.seconds_per_round:.1f} s per round; see {REFINE_JSON})"
    )
    for check in result.checks:
        if not check["held"]:
            out_console.print(f"  not met: {check['what']}: {check['reason']}", markup=False)
