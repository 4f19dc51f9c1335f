"""``holomj assets ...``: import meshes into a library, list, show, remove, build the default
(the jobs: :mod:`holomj.jobs.assets`, which import the asset pipeline when they run)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from holomj.cli.options import JsonOption, LibraryOption, StrictOption
from holomj.cli.output import emit_json, err_console, guard, library_root, out_console

if TYPE_CHECKING:
    from holomj.jobs.assets import ImportRun

assets_app = typer.Typer(help="Manage asset libraries.", no_args_is_help=True)

# the options both import commands take
WorkersOption = Annotated[int, typer.Option(min=1, max=64, help="Parallel processes.")]
PresetOption = Annotated[
    str, typer.Option(help="CoACD settings: fast (seconds), default, fine (minutes).")
]
TimeoutOption = Annotated[float | None, typer.Option(help="CoACD time limit per attempt, seconds.")]
ThumbnailsOption = Annotated[
    bool, typer.Option("--thumbnails/--no-thumbnails", help="Render thumbnails.")
]
AcceptFallbackOption = Annotated[
    bool,
    typer.Option(
        "--accept-fallback",
        help="Cache fallback decompositions (CoACD unavailable, crashed or timed out) as "
        "final and reuse cached ones; without it the next import retries CoACD.",
    ),
]


@assets_app.command("build-default")
def build_default_command(
    library: LibraryOption = None,
    force: Annotated[bool, typer.Option("--force", help="Rebuild even if it is current.")] = False,
) -> None:
    """Build (or refresh) the procedural default library."""
    from holomj.jobs.assets import build_default_library

    built = guard(lambda: build_default_library(library, force=force))
    out_console.print(
        f"default library at {built.root}: {built.assets} assets ({built.seconds:.1f} s)"
    )


@assets_app.command("import")
def import_command(
    paths: Annotated[
        list[Path], typer.Argument(metavar="PATH...", help="Mesh files or folders of them.")
    ],
    library: LibraryOption = None,
    category: Annotated[
        str | None, typer.Option(help="Category (default: guessed from the name).")
    ] = None,
    size: Annotated[
        tuple[float, float, float] | None,
        typer.Option(help="Rescale to this X Y Z size in metres."),
    ] = None,
    description: Annotated[str | None, typer.Option(help="Text description.")] = None,
    mass: Annotated[
        float | None, typer.Option("--mass", help="Mass in kg (default: density x volume).")
    ] = None,
    asset_id: Annotated[
        str | None,
        typer.Option("--id", help="Asset id (one file only; fails if another asset has it)."),
    ] = None,
    up: Annotated[
        str | None,
        typer.Option(help="Up axis of the file: y or z (default: y for glTF, z otherwise)."),
    ] = None,
    front: Annotated[str, typer.Option(help="Source axis the front faces: +x, -x, +y, -y.")] = "+x",
    workers: WorkersOption = 1,
    preset: PresetOption = "default",
    threshold: Annotated[
        float | None, typer.Option(help="CoACD concavity threshold (lower = more hulls).")
    ] = None,
    max_hulls: Annotated[int | None, typer.Option(help="CoACD maximum number of hulls.")] = None,
    timeout: TimeoutOption = None,
    thumbnails: ThumbnailsOption = True,
    accept_fallback: AcceptFallbackOption = False,
    strict: StrictOption = False,
    as_json: JsonOption = False,
) -> None:
    """Import meshes (GLB, glTF, OBJ, STL, PLY) and articulated models (URDF, MJCF) as assets.

    When CoACD is unavailable, crashes or times out, the asset gets a fallback decomposition
    (coarser settings, else the single convex hull) and is reported as degraded: still added
    to the library, marked in its derivation.json, but not cached unless --accept-fallback is
    given, so the next import retries CoACD.

    Exits with 0 when every file was imported (degraded ones included, unless --strict), 1 when
    any failed (the others are kept).
    """
    from holomj.jobs.assets import ImportRun, import_assets

    _run_import(
        ImportRun(
            preset=preset,
            threshold=threshold,
            max_hulls=max_hulls,
            timeout_s=timeout,
            workers=workers,
            thumbnails=thumbnails,
            accept_fallback=accept_fallback,
        ),
        lambda run: import_assets(
            paths,
            library=library,
            asset_id=asset_id,
            category=category,
            size=size,
            description=description,
            mass_kg=mass,
            up=up,
            front=front,
            run=run,
        ),
        as_json=as_json,
        strict=strict,
    )


@assets_app.command("import-objathor")
def import_objathor_command(
    directory: Annotated[
        Path,
        typer.Argument(
            metavar="DIR",
            help="objathor asset folder (with annotations.json.gz and assets/<uid>/ or <uid>/).",
        ),
    ],
    library: LibraryOption = None,
    uids: Annotated[
        list[str] | None,
        typer.Option(
            "--uids", metavar="UID,...", help="Only these uids, comma-separated (default: all)."
        ),
    ] = None,
    colliders: Annotated[
        str,
        typer.Option(
            help="shipped: the assets' own convex colliders (CoACD where an asset has none); "
            "coacd: decompose with CoACD."
        ),
    ] = "shipped",
    workers: WorkersOption = 1,
    preset: PresetOption = "default",
    timeout: TimeoutOption = None,
    thumbnails: ThumbnailsOption = True,
    accept_fallback: AcceptFallbackOption = False,
    strict: StrictOption = False,
    as_json: JsonOption = False,
) -> None:
    """Import Objaverse assets of an objathor folder; each asset's id is its uid.

    Holodeck houses name these uids as assetId, so `holomj compile house.json --library LIB`
    then uses the real assets. Annotations give the category, description, placement, mass
    and receptacle flag; meshes are converted from THOR's Y-up frame to holomj's.

    Exits with 0 when every uid was imported (degraded ones included, unless --strict), 1 when
    any failed (the others are kept), 2 for a bad folder or option.
    """
    from holomj.jobs.assets import ImportRun
    from holomj.jobs.objathor import import_objathor, parse_uids

    _run_import(
        ImportRun(
            preset=preset,
            timeout_s=timeout,
            workers=workers,
            thumbnails=thumbnails,
            accept_fallback=accept_fallback,
        ),
        lambda run: import_objathor(
            directory, library=library, uids=parse_uids(uids), colliders=colliders, run=run
        ),
        as_json=as_json,
        strict=strict,
        full_errors=True,
    )


def _run_import(
    run: ImportRun,
    start: Callable[[ImportRun], Any],
    *,
    as_json: bool,
    strict: bool,
    full_errors: bool = False,
) -> None:
    """Run an import job, ``start(run)`` with ``run``'s progress hooks driving a progress bar;
    then print its summary (and, with ``full_errors``, each failure's whole error) or emit it
    as JSON, and exit with 1 when any failed (or, with ``strict``, was degraded)."""
    columns = (
        TextColumn("[progress.description]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
    )
    with Progress(*columns, console=err_console, disable=as_json, transient=True) as progress:
        task = progress.add_task("importing", total=None)
        hooked = replace(
            run,
            on_planned=lambda total: progress.update(task, total=total),
            on_done=lambda outcome: progress.update(task, advance=1, description=outcome.asset_id),
        )
        result = guard(lambda: start(hooked))
    summary = result.summary
    if as_json:
        emit_json(result.to_dict())
    else:
        _print_summary(result.library, summary, run.accept_fallback)
        if full_errors:
            for o in summary.failed:  # the whole error, unwrapped, whatever the table cut
                err_console.print(f"error: {o.asset_id}: {o.error}", markup=False, soft_wrap=True)
    if summary.failed or (strict and summary.degraded):
        raise typer.Exit(code=1)


def _print_summary(root: Path, summary: Any, accept_fallback: bool) -> None:
    """The import table, a warning line per degraded asset and the counts."""
    table = Table(title=f"imported into {root}")
    for column in ("asset", "result", "hulls", "mass kg", "s"):
        table.add_column(column)
    for o in summary.outcomes:
        table.add_row(
            o.asset_id,
            _result_cell(o),
            str(o.hulls or ""),
            f"{o.mass_kg:.3f}" if o.mass_kg else "",
            f"{o.seconds:.1f}",
        )
    out_console.print(table)
    for o in summary.outcomes:
        if o.id_note:
            out_console.print(f"note: {escape(o.asset_id)}: {escape(o.id_note)}")
    for o in summary.degraded:
        out_console.print(
            f"[yellow]warning: {escape(o.asset_id)}: ok (degraded: {escape(o.degraded_reason)}),"
            f" {o.hulls} hull{'' if o.hulls == 1 else 's'}[/]"
        )
    if summary.degraded and not accept_fallback:
        out_console.print(
            "[yellow]degraded results are not cached: the next import retries CoACD "
            "(--accept-fallback keeps them)[/]"
        )
    out_console.print(
        f"{len(summary.succeeded)} imported, {len(summary.degraded)} degraded, "
        f"{len(summary.failed)} failed"
    )


def _result_cell(outcome: Any) -> str:
    """The result column of one import: ok or cached (yellow when degraded), or the error."""
    if not outcome.ok:
        return f"[red]failed[/]: {escape(outcome.error or '')}"
    result = "cached" if outcome.cached else "ok"
    return f"[yellow]{result} (degraded)[/]" if outcome.degraded else result


@assets_app.command("list")
def list_command(
    library: LibraryOption = None,
    category: Annotated[str | None, typer.Option(help="Only this category.")] = None,
    as_json: JsonOption = False,
) -> None:
    """List the assets of a library (degraded: made from a fallback decomposition)."""
    from holomj.jobs.assets import list_assets

    root = library_root(library)
    listing = guard(lambda: list_assets(root, category))
    rows = listing.rows
    if as_json:
        emit_json(rows)
        return
    table = Table(title=f"{listing.name} ({listing.root}): {len(rows)} assets")
    for column in ("id", "category", "size m", "mass kg", "placement", "surfaces", "colliders"):
        table.add_column(column)
    for r in rows:
        table.add_row(
            r["id"],
            r["category"],
            " x ".join(f"{v:.2f}" for v in r["size_m"]),
            f"{r['mass_kg']:.2f}",
            ",".join(r["placement"]),
            str(r["surfaces"]),
            f"{r['colliders']} [yellow](degraded)[/]" if r["degraded"] else str(r["colliders"]),
        )
    out_console.print(table)


@assets_app.command("show")
def show_command(
    asset_id: Annotated[str, typer.Argument(metavar="ID")],
    library: LibraryOption = None,
) -> None:
    """Print an asset's metadata (and how it was derived) as JSON."""
    from holomj.jobs.assets import show_asset

    root = library_root(library)
    emit_json(guard(lambda: show_asset(root, asset_id)))


@assets_app.command("remove")
def remove_command(
    asset_ids: Annotated[list[str], typer.Argument(metavar="ID...")],
    library: LibraryOption = None,
) -> None:
    """Remove assets from a library."""
    from holomj.jobs.assets import remove_assets

    root = library_root(library)
    guard(lambda: remove_assets(root, asset_ids))
    out_console.print(f"removed {', '.join(asset_ids)} from {root}")
