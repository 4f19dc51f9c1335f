"""``holomj populate SCENE --on OBJECT --objects CAT[:N],...``: spawn-and-drop small objects.

SCENE is a folder written by ``holomj compile`` or ``holomj generate``. The scene's own assets
come from its ``assets/`` library, the new objects' from ``--library`` (default: the default
library). The folder's robot (``robot.json``), if any, stays: candidates are dropped with it in
the world and the scene is recompiled with it. The populated scene is written back into the same
folder atomically: ``scene.xml``, ``scene.json``, ``assets/``, ``objects.json``, ``navmap.json``,
``navmap.png`` and ``robot.json`` afresh; ``report.json``, when the folder has one, replaced by the
validation of the new scene (what ``holomj validate SCENE`` reports: furniture free); and
``populate_report.json`` (every placement outcome; earlier runs are kept under ``runs``).
Everything else is kept as it was; renders and ``report.html`` then show the scene before this
run, which the report lists under ``stale_files`` (``holomj render SCENE`` refreshes them).

Exit codes: 0 when every requested object was placed, 1 when some were not (the scene with the
placed ones and the report are written all the same), 2 for bad input.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from holomj.cli_common import emit_json, guard, out_console

if TYPE_CHECKING:
    from holomj.library.store import AssetLibrary
    from holomj.spec.report import StabilityReport
    from holomj.spec.scene import SceneSpec

POPULATE_REPORT = "populate_report.json"
MAX_SEED = 2**32 - 1
_ITEM = re.compile(r"^\s*([A-Za-z0-9_][A-Za-z0-9_.:|+\- ]*?)\s*(?::\s*(\d+)\s*)?$")


def parse_objects(text: str) -> list[tuple[str, int]]:
    """``"mug:2, book, apple:3"`` -> ``[("mug", 2), ("book", 1), ("apple", 3)]``."""
    from holomj.errors import InputError

    requests = []
    for item in text.split(","):
        if not item.strip():
            continue
        name, count = item.strip(), 1
        head, _, number = name.rpartition(":")
        if head and number.strip().isdigit():
            name, count = head, int(number)
        name = name.strip()
        if not _ITEM.match(name) or count < 1 or count > 1000:
            raise InputError(
                f"bad item {item.strip()!r}",
                where="--objects",
                fix="write CATEGORY[:COUNT],... with 1 <= COUNT <= 1000, e.g. 'mug:2,book'",
            )
        requests.append((name, count))
    if not requests:
        raise InputError("no objects requested", where="--objects", fix="e.g. 'mug:2,book'")
    return requests


@dataclass
class PopulateFolderReport:
    """What ``populate_folder`` did."""

    folder: str
    receptacle: str
    requested: int
    placed: int
    report: dict[str, Any]

    @property
    def all_placed(self) -> bool:
        """True when every requested object was placed."""
        return self.placed == self.requested


def populate_folder(
    folder: Path,
    receptacle_id: str,
    requests: list[tuple[str, int]],
    *,
    seed: int = 0,
    library_path: Path | None = None,
    max_attempts: int = 20,
) -> PopulateFolderReport:
    """Populate the exported scene in ``folder`` and write it back (see the module docstring).

    Raises :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, a bad
    seed or attempt count, an unknown receptacle or request.
    """
    import numpy as np

    from holomj.errors import InputError
    from holomj.export.writer import ASSETS_DIR, SCENE_JSON, export_scene
    from holomj.library.store import AssetLibrary
    from holomj.mjcf.compiler import CompiledScene, compile_scene
    from holomj.physics.scene_io import holomj_folder
    from holomj.physics.spawn import merge_libraries, populate
    from holomj.render.folder import RENDERS_DIR
    from holomj.render.report_html import REPORT_HTML, REPORT_JSON
    from holomj.robots.attach import attach_saved_robot
    from holomj.spec.scene_file import read_scene_file

    folder = Path(folder)
    if holomj_folder(folder) != folder or not folder.is_dir():
        raise InputError(
            "not a holomj scene folder (no scene.json and assets/library.json)",
            where=str(folder),
            fix="pass a folder written by 'holomj compile' or 'holomj generate'",
        )
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"must lie in [0, {MAX_SEED}]", where="--seed")
    if max_attempts < 1 or max_attempts > 1000:
        raise InputError("must lie in [1, 1000]", where="--max-attempts")
    scene = read_scene_file(folder / SCENE_JSON)
    own = AssetLibrary.open(folder / ASSETS_DIR)
    libraries = [own]
    if library_path is not None:
        libraries.append(AssetLibrary.open(library_path))
    library = merge_libraries(*libraries)

    def with_robot(compiled: CompiledScene) -> CompiledScene:
        return attach_saved_robot(compiled, folder)

    result = populate(
        scene,
        library,
        receptacle_id,
        requests,
        np.random.default_rng(seed),
        max_attempts=max_attempts,
        attach=with_robot,
    )
    compiled = with_robot(compile_scene(result.scene, library))
    run = {
        "receptacle": receptacle_id,
        "requests": [{"name": n, "count": c} for n, c in requests],
        "seed": seed,
        "max_attempts": max_attempts,
        **result.to_dict(),
    }
    written: dict[str, Any] = {}
    if (folder / REPORT_JSON).exists():
        validation = _validate(result.scene, library, folder)
        written[REPORT_JSON] = validation.model_dump(mode="json")
        run["validation"] = {
            "ok": validation.ok,
            "furniture": validation.furniture,
            "counts": validation.counts,
        }
    previous = _previous_runs(folder / POPULATE_REPORT)
    # Kept as they are, but made from the scene before this run.
    stale = [name for name in (RENDERS_DIR, REPORT_HTML) if (folder / name).exists()]
    report = {**run, "runs": [*previous, run], "stale_files": stale}
    written[POPULATE_REPORT] = report
    export_scene(compiled, folder, overwrite=True, extra_json=written, keep_from=folder)
    return PopulateFolderReport(
        folder=str(folder),
        receptacle=receptacle_id,
        requested=run["requested"],
        placed=run["placed"],
        report=report,
    )


def _validate(scene: SceneSpec, library: AssetLibrary, folder: Path) -> StabilityReport:
    """The validation ``holomj validate FOLDER`` makes of ``scene`` (with the folder's robot):
    default thresholds, furniture free, no sleeping."""
    from holomj.mjcf.compiler import compile_scene
    from holomj.physics.scene_io import loaded_from_compiled
    from holomj.physics.settle import validate_loaded
    from holomj.robots.attach import attach_saved_robot
    from holomj.spec.report import Thresholds

    compiled = attach_saved_robot(compile_scene(scene, library, furniture="free"), folder)
    loaded = loaded_from_compiled(compiled, library, folder, folder)
    return validate_loaded(loaded, Thresholds(), "free", sleep=False)


def _previous_runs(path: Path) -> list[Any]:
    try:
        runs = json.loads(path.read_text(encoding="utf-8")).get("runs", [])
    except (OSError, ValueError, AttributeError):
        return []
    return runs if isinstance(runs, list) else []


def populate_command(
    scene: Annotated[
        Path,
        typer.Argument(
            metavar="SCENE", help="A folder written by 'holomj compile' or 'holomj generate'."
        ),
    ],
    on: Annotated[str, typer.Option("--on", help="Id of the receptacle object in the scene.")],
    objects: Annotated[
        str,
        typer.Option(
            "--objects", help="Categories or asset ids with counts: CAT[:N],... e.g. mug:2,book."
        ),
    ],
    seed: Annotated[
        int, typer.Option("--seed", min=0, max=MAX_SEED, help="Random seed (0 to 2**32 - 1).")
    ] = 0,
    library: Annotated[
        Path | None,
        typer.Option(
            "--library",
            help="Library of the new objects (default: $HOLOMJ_HOME/library, built on first use).",
        ),
    ] = None,
    max_attempts: Annotated[
        int,
        typer.Option(
            "--max-attempts", min=1, max=1000, help="Candidate poses per object (1-1000)."
        ),
    ] = 20,
    as_json: Annotated[bool, typer.Option("--json", help="Print the report as JSON.")] = False,
) -> None:
    """Drop small objects onto a receptacle of an exported scene and write it back."""
    from holomj.cli_assets import resolve_library

    requests = guard(lambda: parse_objects(objects))
    library_root = resolve_library(library)
    outcome = guard(
        lambda: populate_folder(
            scene,
            on,
            requests,
            seed=seed,
            library_path=library_root,
            max_attempts=max_attempts,
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
