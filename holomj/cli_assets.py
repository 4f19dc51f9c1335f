"""``holomj assets ...``: import meshes into a library, list, show, remove, build the default.

The asset pipeline is imported lazily here: holomj's core never depends on it.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Annotated, Any

import typer
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from holomj.cli_common import LibraryOption, emit_json, err_console, guard, out_console
from holomj.errors import InputError

assets_app = typer.Typer(help="Manage asset libraries.", no_args_is_help=True)


def resolve_library(path: Path | None, create: bool = False) -> Path:
    """The library to use: ``path``, or the default one (built on first use)."""
    from asset_pipeline.default_library import ensure_default_library

    if path is None:
        with err_console.status("building the default asset library (first use)", spinner="dots"):
            return guard(lambda: ensure_default_library())
    if create and not (path / "library.json").exists():
        from asset_pipeline.library_writer import write_library

        guard(
            lambda: write_library(
                path, path.name, [], overwrite=path.exists() and not any(path.iterdir())
            )
        )
    return path


@assets_app.command("build-default")
def build_default_command(
    library: LibraryOption = None,
    force: Annotated[bool, typer.Option("--force", help="Rebuild even if it is current.")] = False,
) -> None:
    """Build (or refresh) the procedural default library."""
    import time

    from asset_pipeline.default_library import ensure_default_library
    from holomj.library.store import AssetLibrary

    start = time.perf_counter()
    root = guard(lambda: ensure_default_library(library, force=force))
    count = len(AssetLibrary.open(root))
    out_console.print(
        f"default library at {root}: {count} assets ({time.perf_counter() - start:.1f} s)"
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
    asset_id: Annotated[str | None, typer.Option("--id", help="Asset id (one file only).")] = None,
    up: Annotated[
        str | None,
        typer.Option(help="Up axis of the file: y or z (default: y for glTF, z otherwise)."),
    ] = None,
    front: Annotated[str, typer.Option(help="Source axis the front faces: +x, -x, +y, -y.")] = "+x",
    workers: Annotated[int, typer.Option(min=1, max=64, help="Parallel processes.")] = 1,
    preset: Annotated[
        str, typer.Option(help="CoACD settings: fast (seconds), default, fine (minutes).")
    ] = "default",
    threshold: Annotated[
        float | None, typer.Option(help="CoACD concavity threshold (lower = more hulls).")
    ] = None,
    max_hulls: Annotated[int | None, typer.Option(help="CoACD maximum number of hulls.")] = None,
    timeout: Annotated[
        float | None, typer.Option(help="CoACD time limit per attempt, seconds.")
    ] = None,
    thumbnails: Annotated[
        bool, typer.Option("--thumbnails/--no-thumbnails", help="Render thumbnails.")
    ] = True,
    accept_fallback: Annotated[
        bool,
        typer.Option(
            "--accept-fallback",
            help="Cache fallback decompositions (CoACD unavailable, crashed or timed out) as "
            "final and reuse cached ones; without it the next import retries CoACD.",
        ),
    ] = False,
    strict: Annotated[
        bool,
        typer.Option(
            "--strict", help="Exit with 1 when any import was degraded (its asset is still added)."
        ),
    ] = False,
    as_json: Annotated[bool, typer.Option("--json", help="Print the summary as JSON.")] = False,
) -> None:
    """Import meshes (GLB, glTF, OBJ, STL, PLY) as simulation-ready assets.

    When CoACD is unavailable, crashes or times out, the asset gets a fallback decomposition
    (coarser settings, else the single convex hull) and is reported as degraded: still added
    to the library, marked in its derivation.json, but not cached unless --accept-fallback is
    given, so the next import retries CoACD.

    Exits with 0 when every file was imported (degraded ones included, unless --strict), 1 when
    any failed (the others are kept).
    """
    from asset_pipeline.manage import plan_jobs, run_imports

    options = guard(
        lambda: _import_options(
            category, size, description, mass, up, front, preset, threshold, max_hulls, timeout
        )
    )
    jobs = guard(lambda: plan_jobs(paths, asset_id))
    root = resolve_library(library, create=True)
    columns = (
        TextColumn("[progress.description]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
    )
    with Progress(*columns, console=err_console, disable=as_json, transient=True) as progress:
        task = progress.add_task("importing", total=len(jobs))
        summary = guard(
            lambda: run_imports(
                jobs,
                root,
                options,
                workers=workers,
                thumbnails=thumbnails,
                on_done=lambda outcome: progress.update(
                    task, advance=1, description=outcome.asset_id
                ),
                accept_fallback=accept_fallback,
            )
        )
    if as_json:
        emit_json({"library": str(root), **summary.to_dict()})
    else:
        _print_summary(root, summary, accept_fallback)
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


def _import_options(
    category, size, description, mass, up, front, preset, threshold, max_hulls, timeout
) -> Any:
    from asset_pipeline.importer import ImportOptions
    from asset_pipeline.manage import coacd_params

    if up not in (None, "y", "z"):
        raise InputError(f"unknown up axis {up!r}", where="--up", fix="use y or z")
    if front not in ("+x", "-x", "+y", "-y"):
        raise InputError(f"unknown front {front!r}", where="--front", fix="use +x, -x, +y or -y")
    coacd = coacd_params(preset, threshold=threshold, max_convex_hull=max_hulls, timeout_s=timeout)
    return ImportOptions(
        category=category,
        size=size,
        description=description,
        mass_kg=mass,
        up_axis=up,
        front=front,
        coacd=coacd,
    )


@assets_app.command("list")
def list_command(
    library: LibraryOption = None,
    category: Annotated[str | None, typer.Option(help="Only this category.")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """List the assets of a library (degraded: made from a fallback decomposition)."""
    from holomj.library.store import AssetLibrary, normalise_category

    root = resolve_library(library)
    lib = guard(lambda: AssetLibrary.open(root))
    assets = [lib.get(i) for i in lib.ids()]
    if category is not None:
        wanted = normalise_category(category)
        assets = [a for a in assets if normalise_category(a.meta.category) == wanted]
    rows = [
        {
            "id": a.meta.id,
            "category": a.meta.category,
            "size_m": [round(v, 3) for v in a.meta.size],
            "mass_kg": round(a.meta.mass, 3),
            "placement": a.meta.placement,
            "surfaces": len(a.meta.surfaces),
            "colliders": len(a.meta.collision),
            "degraded": _is_degraded(a.root),
        }
        for a in assets
    ]
    if as_json:
        emit_json(rows)
        return
    table = Table(title=f"{lib.name} ({root}): {len(rows)} assets")
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


def _is_degraded(asset_root: Path) -> bool:
    """Whether the asset's ``derivation.json`` marks it degraded (False when there is none)."""
    derivation = asset_root / "derivation.json"
    if not derivation.is_file():
        return False
    try:
        return bool(json.loads(derivation.read_text()).get("degraded"))
    except (OSError, ValueError, AttributeError):
        return False


@assets_app.command("show")
def show_command(
    asset_id: Annotated[str, typer.Argument(metavar="ID")],
    library: LibraryOption = None,
) -> None:
    """Print an asset's metadata (and how it was derived) as JSON."""
    from holomj.library.store import AssetLibrary

    root = resolve_library(library)
    asset = guard(lambda: AssetLibrary.open(root).get(asset_id))
    data: dict[str, Any] = {"folder": str(asset.root), "meta": asset.meta.model_dump(mode="json")}
    derivation = asset.root / "derivation.json"
    if derivation.is_file():
        data["derivation"] = json.loads(derivation.read_text())
    sys.stdout.write(json.dumps(data, indent=2, sort_keys=True) + "\n")


@assets_app.command("remove")
def remove_command(
    asset_ids: Annotated[list[str], typer.Argument(metavar="ID...")],
    library: LibraryOption = None,
) -> None:
    """Remove assets from a library."""
    from asset_pipeline.library_writer import remove_assets

    root = resolve_library(library)
    guard(lambda: remove_assets(root, asset_ids))
    out_console.print(f"removed {', '.join(asset_ids)} from {root}")
