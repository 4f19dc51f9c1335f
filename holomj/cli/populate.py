"""``holomj populate OUT --on OBJECT [--objects CAT[:N],... | --count N]``: spawn-and-drop
small objects (the job: :mod:`holomj.jobs.populate`); without ``--objects``, ``--count`` of them
drawn from what sits on such a receptacle in AI2-THOR (:mod:`holomj.jobs.receptacle_priors`).

OUT is a folder written by ``holomj compile`` or ``holomj generate``. The scene's own assets
come from its ``assets/`` library, the new objects' from ``--library`` (default: the default
library). The folder's robot (``robot.json``), if any, stays: candidates are dropped with it in
the world and the scene is recompiled with it. The populated scene is written back into the same
folder atomically: ``scene.xml``, ``scene.json``, ``assets/``, ``objects.json``, ``navmap.json``,
``navmap.png`` and ``robot.json`` afresh; ``report.json``, when the folder has one, replaced by the
validation of the new scene (what ``holomj validate SCENE`` reports: furniture free); and
``populate_report.json`` (every placement outcome; earlier runs are kept under ``runs``).
Everything else is kept as it was; renders and ``report.html`` then show the scene before this
run, which the report lists under ``stale_files`` (``holomj render OUT`` refreshes them).

With ``--instruction TEXT --planner llm`` a vision-language model (the ``[llm]`` configuration of
``holomj generate --planner llm``) is shown a render of the receptacle from above, names the
next small object and points at a pixel where it goes; the pixel's ray meets the receptacle's
surface and the object is dropped there; up to ``--count`` objects (the records are in
``populate_report.json``: ``pointing``). Offline (``--planner offline``, or no LLM configured)
the instruction's small objects are dropped, or the receptacle priors decide.

Exit codes: 0 when every requested object was placed, 1 when some were not (the scene with the
placed ones and the report are written all the same), 2 for bad input.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from holomj.cli.options import (
    FolderArg,
    JsonOption,
    LibraryOption,
    LlmConfigOption,
    LlmKeyOption,
    LlmModelOption,
    LlmUrlOption,
    PlannerOption,
    SeedOption,
    llm_settings,
)
from holomj.cli.output import emit_json, err_console, guard, library_root, out_console
from holomj.file_names import POPULATE_REPORT

if TYPE_CHECKING:
    from holomj.jobs.populate import PopulateResult


OnOption = Annotated[str, typer.Option("--on", help="Id of the receptacle object in the scene.")]
ObjectsOption = Annotated[
    str | None,
    typer.Option(
        "--objects",
        help="Categories or asset ids with counts: CAT[:N],... e.g. mug:2,book. Without "
        "it, --count objects are drawn from what sits on such a receptacle in AI2-THOR.",
    ),
]
CountOption = Annotated[
    int,
    typer.Option(
        "--count",
        min=1,
        max=20,
        help="Objects drawn when --objects is not given (with --instruction: at most).",
    ),
]
InstructionOption = Annotated[
    str | None,
    typer.Option(
        "--instruction",
        "-i",
        help="What to put on it, in words (instead of --objects); with --planner llm the "
        "model names each object and points at where it goes.",
    ),
]
ImagesOption = Annotated[
    bool,
    typer.Option("--images/--no-images", help="Send the render to the LLM (else text only)."),
]
MaxAttemptsOption = Annotated[
    int,
    typer.Option("--max-attempts", min=1, max=1000, help="Candidate poses per object (1-1000)."),
]


def populate_command(
    scene: FolderArg,
    on: OnOption,
    objects: ObjectsOption = None,
    count: CountOption = 3,
    instruction: InstructionOption = None,
    planner: PlannerOption = "offline",
    images: ImagesOption = True,
    llm_base_url: LlmUrlOption = None,
    llm_model: LlmModelOption = None,
    llm_api_key: LlmKeyOption = None,
    llm_config: LlmConfigOption = None,
    seed: SeedOption = 0,
    library: LibraryOption = None,
    max_attempts: MaxAttemptsOption = 20,
    as_json: JsonOption = False,
) -> None:
    """Drop small objects onto a receptacle of an exported scene and write it back."""
    from holomj.jobs.populate import parse_objects, populate_folder

    requests = guard(lambda: parse_objects(objects)) if objects is not None else None
    settings = llm_settings(llm_base_url, llm_model, llm_api_key, llm_config)
    library_path = library_root(library)
    outcome = guard(
        lambda: populate_folder(
            scene,
            on,
            requests,
            seed=seed,
            library_path=library_path,
            max_attempts=max_attempts,
            count=count,
            instruction=instruction,
            planner=planner,
            llm_config=settings,
            images=None if images else False,
            log=None if as_json else lambda line: err_console.print(line, markup=False),
        )
    )
    if as_json:
        emit_json(outcome.report.to_dict())
    else:
        _print_outcome(outcome, on)
    if not outcome.all_placed:
        raise typer.Exit(code=1)


def _print_outcome(outcome: PopulateResult, on: str) -> None:
    """What was placed and what not, the validation and the files now stale."""
    report = outcome.report
    colour = "green" if outcome.all_placed else "yellow"
    out_console.print(
        f"[bold {colour}]placed {outcome.placed}/{outcome.requested}[/] on {on} "
        f"-> {outcome.folder} (see {POPULATE_REPORT})"
    )
    for note in report.notes or []:
        out_console.print(f"  note: {note}", markup=False)
    if report.drawn_from and report.drawn_from != "llm pointing":
        names = ", ".join(f"{r.name}:{r.count}" for r in report.requests)
        out_console.print(f"  drawn from the {report.drawn_from} statistics: {names}", markup=False)
    for placement in report.placements:
        if not placement["accepted"]:
            out_console.print(
                f"  [yellow]not placed:[/] {placement['object_id']} ({placement['asset']}): "
                f"{placement['reason']} after {placement['attempts']} attempts",
                markup=True,
            )
    validation = report.validation
    if validation is not None:
        counts = validation.counts
        verdict = "[green]ok[/]" if validation.ok else "[red]NOT ok[/]"
        out_console.print(
            f"  report.json rewritten: validation {verdict}, {counts['stable']}/"
            f"{counts['objects']} stable (furniture {validation.furniture})"
        )
    if report.stale_files:
        out_console.print(
            f"  {' and '.join(report.stale_files)} show the scene before this "
            f"run: 'holomj render {outcome.folder}' refreshes them",
            markup=False,
        )
