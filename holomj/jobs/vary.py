"""The vary job (``holomj vary OUT -n N [-o DIR] [--seed S]``): variants of one scene's layout.

Each variant is the scene edited by the edit job (:func:`holomj.jobs.edit.apply_edits`) with
operations drawn from its own random stream (:func:`variant_operations`):

- ``material``: every room's floor and walls get a material drawn from the material library;
- ``light``: every light of the scene gets its energy and colour jittered (a scene lit only by
  the default lights gets one ceiling light per room, of a jittered energy and colour);
- ``replace``: up to ``replace`` pieces of floor furniture whose category has several assets in
  the source library are replaced by an asset of that category, at the same place (the edit's
  footprint check keeps them clear of walls and others); objects named by the scene's tasks
  are kept, so the tasks keep their handles and joints;
- ``move`` with ``on``: every small object is dropped again onto its own receptacle at a
  random free spot (the populate drop).

The edited scene is validated as ``holomj validate`` does; a variant that does not validate is
drawn again with a new stream (``tries`` in all) and reported when none validates. A variant is
written atomically as ``DIR/variant_000`` (a failure leaves no half folder). When the source has
``tasks.json``, the variant keeps the tasks whose objects, receptacles, rooms and joints it still
has (the others are listed as dropped).
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from holomj.atomic import replace_folder, write_file
from holomj.errors import HolomjError, InputError
from holomj.file_names import TASKS_JSON
from holomj.jobs.edit import apply_edits
from holomj.jobs.folder import open_library, read_scene, require_scene_folder
from holomj.jobs.tasks import read_objects, read_tasks
from holomj.library.store import AssetLibrary
from holomj.retrieval.materials import MaterialLibrary
from holomj.seeds import MAX_SEED
from holomj.spec.scene import SceneSpec
from holomj.spec.tasks import TaskSet

ENERGY_RANGE = (0.7, 1.3)  # factor on a light's energy
FIXTURE_ENERGY = (0.6, 1.2)  # energy of a ceiling light added to a scene without lights
COLOR_JITTER = 0.12  # at most this much off white (warm or cool), per channel
VARIANT_PREFIX = "variant_"
FOOTPRINT_RATIO = 1.6  # a replacement's depth and width: at most this factor off
MAX_DESCRIPTION = 200


@dataclass
class VariantResult:
    """One variant: where it is, whether it validated, how many draws it took, the operations
    applied and refused, and the tasks kept and dropped."""

    name: str
    path: str | None
    ok: bool
    tries: int
    seconds: float
    edit_seed: int
    applied: int = 0
    refused: list[str] = field(default_factory=list)
    operations: list[dict[str, Any]] = field(default_factory=list)
    validation: dict[str, Any] | None = None
    tasks_kept: list[str] = field(default_factory=list)
    tasks_dropped: list[str] = field(default_factory=list)


@dataclass
class VaryResult:
    """What :func:`vary_folder` made."""

    source: str
    out_dir: str
    seed: int
    variants: list[VariantResult] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def validated(self) -> int:
        return sum(1 for variant in self.variants if variant.ok)

    def to_dict(self) -> dict[str, Any]:
        return {**asdict(self), "validated": self.validated}


@dataclass(frozen=True)
class VarySources:
    """What variants are drawn from: the scene's own assets, the source library (None: no
    replacements), the material library, and the object ids the tasks name (never replaced)."""

    own: AssetLibrary
    source: AssetLibrary | None
    materials: MaterialLibrary
    kept: frozenset[str] = frozenset()
    replace: int = 1
    library_path: Path | None = None
    materials_path: Path | None = None


def default_out_dir(folder: Path) -> Path:
    """Where variants go when no ``-o`` is given: ``<OUT>_variants`` beside the folder."""
    folder = Path(folder).absolute()
    return folder.parent / f"{folder.name}_variants"


def vary_folder(
    out: Path | str,
    count: int,
    out_dir: Path | str | None = None,
    *,
    seed: int = 0,
    tries: int = 3,
    replace: int = 1,
    library_path: Path | None = None,
    materials: Path | None = None,
    log: Callable[[str], None] | None = None,
) -> VaryResult:
    """Write ``count`` validated variants of the scene folder ``out`` into ``out_dir`` (see the
    module docstring). ``library_path``: the library replacements come from (None: none are
    drawn); ``materials``: the material library (None: the built-in one)."""
    start = time.perf_counter()
    folder = require_scene_folder(Path(out), "holomj generate' or 'holomj compile")
    if count < 1 or tries < 1:
        raise InputError("must be at least 1", where="-n" if count < 1 else "--tries")
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"must lie in [0, {MAX_SEED}]", where="--seed")
    target_dir = Path(out_dir) if out_dir is not None else default_out_dir(folder)
    if target_dir.absolute() == folder.absolute():
        raise InputError("variants cannot replace their source", where=str(target_dir))
    tasks = read_tasks(folder) if (folder / TASKS_JSON).is_file() else None
    sources = VarySources(
        own=open_library(folder),
        source=AssetLibrary.open(library_path) if library_path is not None else None,
        materials=MaterialLibrary.load(materials),
        kept=frozenset(task_objects(tasks)) if tasks is not None else frozenset(),
        replace=replace,
        library_path=library_path,
        materials_path=materials,
    )
    scene = read_scene(folder)
    result = VaryResult(str(folder), str(target_dir), seed)
    for index in range(count):
        variant = _make_variant(folder, scene, sources, tasks, target_dir, (seed, index, tries))
        result.variants.append(variant)
        if log is not None:
            state = "ok" if variant.ok else "NOT VALID"
            log(f"{variant.name}: {state} after {variant.tries} draw(s), {variant.seconds:.1f} s")
    result.seconds = round(time.perf_counter() - start, 3)
    return result


def _make_variant(
    folder: Path,
    scene: SceneSpec,
    sources: VarySources,
    tasks: TaskSet | None,
    target_dir: Path,
    key: tuple[int, int, int],
) -> VariantResult:
    """Draw variant ``key[1]`` until it validates (``key[2]`` draws at most) and write it."""
    seed, index, tries = key
    name = f"{VARIANT_PREFIX}{index:03d}"
    start = time.perf_counter()
    variant = VariantResult(name, None, False, 0, 0.0, 0)
    for attempt in range(tries):
        rng = np.random.default_rng([seed, index, attempt])
        ops = variant_operations(scene, sources, rng)
        variant = VariantResult(
            name, None, False, attempt + 1, 0.0, int(rng.integers(0, MAX_SEED)), operations=ops
        )
        try:
            replace_folder(
                target_dir / name, functools.partial(_fill, folder, sources, tasks, variant)
            )
        except _NotValid:
            continue
        variant.path = str(target_dir / name)
        variant.ok = True
        break
    variant.seconds = round(time.perf_counter() - start, 3)
    return variant


class _NotValid(HolomjError):
    """A drawn variant failed validation (drawn again; never leaves the job)."""


def _fill(
    folder: Path,
    sources: VarySources,
    tasks: TaskSet | None,
    variant: VariantResult,
    tmp: Path,
) -> None:
    """Write ``variant``'s edited scene into ``tmp``; raise :class:`_NotValid` when it does
    not validate. Its tasks are the source's that it still makes possible."""
    report = apply_edits(
        folder,
        variant.operations,
        tmp,
        seed=variant.edit_seed,
        library_path=sources.library_path,
        overwrite=True,
        materials=sources.materials_path,
    )
    variant.applied = report.applied
    variant.refused = [
        f"{result.op}: {result.reason}"
        for result in report.operations
        if result.status == "refused"
    ]
    variant.validation = report.validation
    if not (report.validation or {}).get("ok"):
        raise _NotValid("the variant does not validate")
    if tasks is not None:
        kept = still_possible(tasks, read_objects(tmp))
        variant.tasks_kept = [task.id for task in kept.tasks]
        variant.tasks_dropped = [t.id for t in tasks.tasks if t.id not in variant.tasks_kept]
        write_file(tmp / TASKS_JSON, kept.model_dump_json(indent=2) + "\n")


def variant_operations(
    scene: SceneSpec, sources: VarySources, rng: np.random.Generator
) -> list[dict[str, Any]]:
    """The edit operations of one variant (see the module docstring), drawn with ``rng``."""
    return [
        *_material_ops(scene, sources.materials, rng),
        *_light_ops(scene, rng),
        *_replace_ops(scene, sources, rng, sources.replace),
        *_redrop_ops(scene),
    ]


def _material_ops(
    scene: SceneSpec, materials: MaterialLibrary, rng: np.random.Generator
) -> list[dict[str, Any]]:
    ops = []
    for surface, op_surface in (("floor", "floor"), ("wall", "walls")):
        names = sorted(entry.name for entry in materials.for_surface(surface))
        if not names:
            continue
        for room in scene.rooms:
            material = names[int(rng.integers(len(names)))]
            ops.append(
                {"op": "material", "room": room.id, "surface": op_surface, "material": material}
            )
    return ops


def _jittered_color(rng: np.random.Generator) -> list[float]:
    """Near white: warmer (more red) or cooler (more blue) by up to :data:`COLOR_JITTER`."""
    warmth = float(rng.uniform(-1.0, 1.0)) * COLOR_JITTER
    green = 1.0 - abs(warmth) / 2
    return [round(min(1.0, 1.0 + warmth), 3), round(green, 3), round(min(1.0, 1.0 - warmth), 3)]


def _light_ops(scene: SceneSpec, rng: np.random.Generator) -> list[dict[str, Any]]:
    if scene.lights:
        return [
            {
                "op": "light",
                "id": light.id,
                "color": _jittered_color(rng),
                "energy": round(min(100.0, light.energy * float(rng.uniform(*ENERGY_RANGE))), 3),
            }
            for light in scene.lights
        ]
    return [
        {
            "op": "light",
            "room": room.id,
            "color": _jittered_color(rng),
            "energy": round(float(rng.uniform(*FIXTURE_ENERGY)), 3),
        }
        for room in scene.rooms
    ]


def _replace_ops(
    scene: SceneSpec, sources: VarySources, rng: np.random.Generator, count: int
) -> list[dict[str, Any]]:
    """Replace up to ``count`` pieces of floor furniture (not named by a task) by another asset
    of their category of a like footprint (asked for by its description)."""
    if sources.source is None or count < 1:
        return []
    candidates = []
    for obj in scene.objects:
        if obj.support is not None or obj.id in sources.kept or obj.asset not in sources.own:
            continue
        meta = sources.own.get(obj.asset).meta
        others = [
            asset.meta.description
            for asset in sources.source.by_category(meta.category)
            if asset.meta.id != obj.asset
            and asset.meta.description
            and _like_footprint(meta.size, asset.meta.size)
        ]
        if others:
            candidates.append((obj.id, meta.category, sorted(others)))
    ops = []
    for i in sorted(int(i) for i in rng.permutation(len(candidates))[:count]):
        object_id, category, descriptions = candidates[i]
        description = descriptions[int(rng.integers(len(descriptions)))]
        ops.append(
            {
                "op": "replace",
                "id": object_id,
                "category": category,
                "description": description[:MAX_DESCRIPTION],
            }
        )
    return ops


def _like_footprint(size: tuple[float, ...], other: tuple[float, ...]) -> bool:
    """Depth and width each within :data:`FOOTPRINT_RATIO` of the other's."""
    return all(
        max(a, b) <= FOOTPRINT_RATIO * min(a, b) for a, b in zip(size[:2], other[:2], strict=True)
    )


def _redrop_ops(scene: SceneSpec) -> list[dict[str, Any]]:
    """Every small object dropped again onto its receptacle (riders of small objects stay)."""
    carried = {obj.support for obj in scene.objects if obj.support is not None}
    small = {obj.id for obj in scene.objects if obj.support is not None}
    return [
        {"op": "move", "id": obj.id, "on": obj.support}
        for obj in scene.objects
        if obj.support is not None and obj.support not in small and obj.id not in carried
    ]


def task_objects(tasks: TaskSet) -> set[str]:
    """Every object and receptacle id the tasks name."""
    names: set[str] = set()
    for task in tasks.tasks:
        _collect(task.model_dump(mode="json"), ("object", "receptacle"), names)
    return names


def _collect(value: Any, keys: tuple[str, ...], into: set[str]) -> None:
    if isinstance(value, dict):
        for key, item in value.items():
            if key in keys and isinstance(item, str):
                into.add(item)
            else:
                _collect(item, keys, into)
    elif isinstance(value, list):
        for item in value:
            _collect(item, keys, into)


def still_possible(tasks: TaskSet, objects: dict[str, Any]) -> TaskSet:
    """The tasks whose objects, receptacles, rooms and joints ``objects`` (an objects.json)
    still has."""
    have = {
        "object": {o["id"] for o in objects.get("objects", [])},
        "room": {r["id"] for r in objects.get("rooms", []) if isinstance(r, dict) and "id" in r},
        "joint": {j["name"] for o in objects.get("objects", []) for j in o.get("joints") or []},
    }
    have["receptacle"] = have["object"]
    kept = []
    for task in tasks.tasks:
        named: dict[str, set[str]] = {}
        for key in have:
            named[key] = set()
            _collect(task.model_dump(mode="json"), (key,), named[key])
        if all(named[key] <= have[key] for key in have):
            kept.append(task)
    return tasks.model_copy(update={"tasks": kept})
