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

Exit codes: 0 when every requested object was placed, 1 when some were not (the scene with the
placed ones and the report are written all the same), 2 for bad input.
"""

from __future__ import annotations

from typing import Annotated

import typer

from holomj.cli.options import FolderArg, JsonOption, LibraryOption, SeedOption
from holomj.cli.output import emit_json, guard, library_root, out_console


def populate_command(
    scene: FolderArg,
    on: Annotated[str, typer.Option("--on", help="Id of the receptacle object in the scene.")],
    objects: Annotated[
        str | None,
        typer.Option(
            "--objects",
            help="Categories or asset ids with counts: CAT[:N],... e.g. mug:2,book. Without "
            "it, --count objects are drawn from what sits on such a receptacle in AI2-THOR.",
        ),
    ] = None,
    count: Annotated[
        int,
        typer.Option("--count", min=1, max=20, help="Objects drawn when --objects is not given."),
    ] = 3,
    seed: SeedOption = 0,
    library: LibraryOption = None,
    max_attempts: Annotated[
        int,
        typer.Option(
            "--max-attempts", min=1, max=1000, help="Candidate poses per object (1-1000)."
        ),
    ] = 20,
    as_json: JsonOption = False,
) -> None:
    """Drop small objects onto a receptacle of an exported scene and write it back."""
    from holomj.jobs.folder import POPULATE_REPORT
    from holomj.jobs.populate import parse_objects, populate_folder

    requests = guard(lambda: parse_objects(objects)) if objects is not None else None
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
        )
    )
    if as_json:
        emit_json(outcome.report)
    else:
        colour = "green" if outcome.all_placed else "yellow"
        out_console.print(
            f"[bold {colour}]placed {outcome.placed}/{outcome.requested}[/] on {on} "
            f"-> {outcome.folder} (see {POPULATE_REPORT})"
        )
        if outcome.report.get("drawn_from"):
            names = ", ".join(f"{r['name']}:{r['count']}" for r in outcome.report["requests"])
            out_console.print(
                f"  drawn from the {outcome.report['drawn_from']} statistics: {names}",
                markup=False,
            )
        for placement in outcome.report["placements"]:
            if not placement["accepted"]:
                out_console.print(
                    f"  [yellow]not placed:[/] {placement['object_id']} ({placement['asset']}): "
                    f"{placement['reason']} after {placement['attempts']} attempts",
                    markup=True,
                )
        validation = outcome.report.get("validation")
        if validation is not None:
            counts = validation["counts"]
            verdict = "[green]ok[/]" if validation["ok"] else "[red]NOT ok[/]"
            out_console.print(
                f"  report.json rewritten: validation {verdict}, {counts['stable']}/"
                f"{counts['objects']} stable (furniture {validation['furniture']})"
            )
        if outcome.report["stale_files"]:
            out_console.print(
                f"  {' and '.join(outcome.report['stale_files'])} show the scene before this "
                f"run: 'holomj render {outcome.folder}' refreshes them",
                markup=False,
            )
    if not outcome.all_placed:
        raise typer.Exit(code=1)
