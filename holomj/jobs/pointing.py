"""Populate by pointing (``holomj populate OUT --on ID --instruction TEXT --planner llm``).

For each of up to ``count`` objects:

1. render the receptacle from straight above (:func:`holomj.jobs.refine_views.render_receptacle`;
   the scene as populated so far);
2. ask the model to **name** the next small object (or to say it is done);
3. **retrieve** an asset for it, or make one on demand, as ``holomj edit``'s ``add_on`` does
   (a name that is not a small object is sent back);
4. ask the model to **point** at a pixel; the pixel's ray (the render camera's intrinsics and
   extrinsics) meets the receptacle's support surfaces
   (:func:`holomj.refinement.pointing.hit_surface`);
   a pixel off the image or off the surface is sent back with where it went;
5. **drop** the object there: spawn-and-drop (:func:`holomj.physics.spawn.populate`) on the hit
   surface cut down to a disc around the point (the object's footprint radius plus 3 cm, then
   8 cm when that finds no place), so it is spawned within a few centimetres of the point,
   dropped, settled and accepted only when it rests on the receptacle; a failed drop is sent
   back ("it did not come to rest there: ...; point at another free spot").

Every step's answer is checked as JSON and nothing in it is executed; each object's record has
the name, asset, pixel, camera, world point, surface, the drop's outcome and the distance from
the pointed spot, with the model's tokens, images and seconds.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from holomj.errors import HolomjError, InputError
from holomj.jobs.pointed_drop import drop_at
from holomj.library.store import AssetLibrary
from holomj.plan.llm_json import LLMResponseError
from holomj.spec.scene import SceneSpec


@dataclass
class PointingOutcome:
    """The populated scene and every object's record."""

    scene: SceneSpec
    records: list[dict[str, Any]] = field(default_factory=list)
    placed: int = 0
    asked: int = 0
    done: bool = False
    usage: dict[str, Any] = field(default_factory=dict)


def populate_by_pointing(
    folder: Path,
    scene: SceneSpec,
    receptacle_id: str,
    instruction: str,
    *,
    count: int,
    chat: Any,
    own: AssetLibrary,
    source: AssetLibrary | None,
    seed: int,
    max_attempts: int,
    attach: Callable[[Any], Any] | None,
    width: int = 400,
    height: int = 300,
    log: Callable[[str], None] | None = None,
) -> PointingOutcome:
    """Name, point and drop up to ``count`` objects (see the module docstring)."""
    from holomj.edit.state import EditContext
    from holomj.physics.spawn_requests import find_object
    from holomj.physics.surfaces_world import world_surfaces

    synthesiser = None
    if source is not None:
        from holomj.jobs.synthesis import LibrarySynthesiser

        synthesiser = LibrarySynthesiser(source)
    ctx = EditContext(own=own, source=source, synthesiser=synthesiser, seed=seed, attach=attach)
    receptacle = find_object(scene, receptacle_id)
    meta = ctx.library.get(receptacle.asset).meta
    if not world_surfaces(receptacle, meta):
        raise InputError(
            f"object {receptacle_id!r} (asset {meta.id!r}) has no support surfaces",
            where="--on",
            fix="choose a table, desk, shelf or other receptacle",
        )
    pointer = _Pointer(
        folder, receptacle_id, instruction, ctx, chat, count, seed, max_attempts, attach,
        (width, height), log or (lambda line: None),
    )  # fmt: skip
    outcome = PointingOutcome(scene=scene)
    for number in range(count):
        if not pointer.one(outcome, number):
            break
    outcome.usage = pointer.usage
    return outcome


class _Pointer:
    """Names, points and drops one object at a time."""

    def __init__(
        self,
        folder: Path,
        receptacle_id: str,
        instruction: str,
        ctx: Any,
        chat: Any,
        count: int,
        seed: int,
        max_attempts: int,
        attach: Callable[[Any], Any] | None,
        size: tuple[int, int],
        emit: Callable[[str], None],
    ) -> None:
        self.folder, self.receptacle_id, self.instruction = folder, receptacle_id, instruction
        self.ctx, self.chat, self.count, self.seed = ctx, chat, count, seed
        self.max_attempts, self.attach, self.size, self.emit = max_attempts, attach, size, emit
        self.usage: dict[str, Any] = {
            "calls": 0,
            "prompt_tokens": 0,
            "completion_tokens": 0,
            "images_sent": 0,
            "image_bytes": 0,
            "seconds": 0.0,
        }

    def account(self, record: dict[str, Any]) -> None:
        for key in ("calls", "prompt_tokens", "completion_tokens", "image_bytes"):
            self.usage[key] += int(record.get(key, 0))
        self.usage["images_sent"] += int(record.get("images", 0))
        self.usage["seconds"] = round(self.usage["seconds"] + float(record.get("seconds", 0.0)), 3)

    def one(self, outcome: PointingOutcome, number: int) -> bool:
        """Name, point at and drop object ``number``; False when pointing should stop."""
        start = time.perf_counter()
        look = self._look(outcome)
        record: dict[str, Any] = {"number": number, "camera": look.view.camera.to_json()}
        outcome.records.append(record)
        named = self._ask_name(outcome, number, look, record)
        if named is None:
            return False
        self._ask_point(outcome, number, look, record, named, start)
        return True

    def _look(self, outcome: PointingOutcome) -> _View:
        """The receptacle seen from above in the scene as it is now, with its surfaces."""
        from holomj.mjcf.compiler import compile_scene
        from holomj.physics.spawn_requests import find_object
        from holomj.physics.surfaces_world import world_surfaces

        library = self.ctx.library
        receptacle = find_object(outcome.scene, self.receptacle_id)
        meta = library.get(receptacle.asset).meta
        surfaces = world_surfaces(receptacle, meta)
        compiled = compile_scene(outcome.scene, library)
        if self.attach is not None:
            compiled = self.attach(compiled)
        width, height = self.size
        view = _render(self.folder, self.receptacle_id, surfaces, compiled, width, height)
        caption = f"{self.receptacle_id} seen from straight above ({width} x {height} pixels)"
        on_it = [
            f"{o.id} ({library.get(o.asset).meta.category if o.asset in library else o.asset})"
            for o in outcome.scene.objects
            if o.support == self.receptacle_id
        ]
        return _View(view, surfaces, meta.category, caption, on_it)

    def _ask_name(
        self, outcome: PointingOutcome, number: int, look: _View, record: dict[str, Any]
    ) -> tuple[str, dict[str, Any]] | None:
        """The next object the model names and the asset retrieved for it; None when the model
        failed or said the instruction is fulfilled (recorded)."""
        from holomj.refinement import pointing

        question = pointing.name_question(
            self.instruction, self.receptacle_id, look.category, look.on_it, self.count - number
        )
        retrieved: dict[str, Any] = {}

        def parse_name(content: str) -> str | None:
            name = pointing.parse_name(content)
            if name is not None:
                retrieved.clear()
                retrieved.update(
                    _retrieve(self.ctx, outcome.scene, self.receptacle_id, name, number)
                )
            return name

        try:
            name, step = self.chat.ask(
                f"name {number}",
                question,
                [(look.caption, look.view.png)],
                parse_name,
                system=pointing.SYSTEM,
            )
        except HolomjError as err:
            self.account(getattr(err, "record", {}))
            record.update(status="failed", reason=err.one_line())
            self.emit(f"pointing {number}: {err.one_line()}")
            return None
        self.account(step)
        record["name_step"] = step
        outcome.asked += 1
        if name is None:
            record.update(status="done", reason="the model said the instruction is fulfilled")
            outcome.done = True
            return None
        record.update(name=name, **retrieved)
        return name, retrieved

    def _ask_point(
        self,
        outcome: PointingOutcome,
        number: int,
        look: _View,
        record: dict[str, Any],
        named: tuple[str, dict[str, Any]],
        start: float,
    ) -> None:
        """Ask where the named object goes and drop it there (the record says how it went)."""
        from holomj.refinement import pointing

        name, retrieved = named
        camera = look.view.camera
        placed: dict[str, Any] = {}

        def parse_point(content: str) -> tuple[int, int]:
            u, v = pointing.parse_pixel(content, camera.width, camera.height)
            hit = pointing.hit_surface(camera, u, v, look.surfaces)
            scene_after, drop = drop_at(
                outcome.scene, self.ctx, self.receptacle_id, retrieved["asset"], hit, self.seed,
                number, self.max_attempts,
            )  # fmt: skip
            if scene_after is None:
                raise LLMResponseError(
                    f"the {name} did not come to rest at pixel ({u}, {v}) "
                    f"({drop['reason']}); point at another free spot of the surface"
                )
            placed.update(scene=scene_after, drop=drop, hit=hit)
            return u, v

        try:
            pixel, step = self.chat.ask(
                f"point {number}",
                pointing.point_question(name, camera.width, camera.height),
                [(look.caption, look.view.png)],
                parse_point,
                system=pointing.SYSTEM,
            )
        except HolomjError as err:
            self.account(getattr(err, "record", {}))
            record.update(status="not placed", reason=err.one_line())
            record["seconds"] = round(time.perf_counter() - start, 3)
            self.emit(f"pointing {number}: {name}: {err.one_line()}")
            return
        self.account(step)
        hit = placed["hit"]
        outcome.scene = placed["scene"]
        outcome.placed += 1
        record.update(
            status="placed",
            pixel=list(pixel),
            point_step=step,
            surface_index=hit.index,
            world_point=[round(v, 4) for v in hit.point],
            **placed["drop"],
            seconds=round(time.perf_counter() - start, 3),
        )
        self.emit(
            f"pointing {number}: {name} -> {placed['drop']['object_id']} at pixel {pixel}, "
            f"{placed['drop']['distance_m'] * 100:.1f} cm from the pointed spot"
        )


@dataclass(frozen=True)
class _View:
    """What the model is shown: the render, the receptacle's surfaces in the world, its
    category, the image's caption and what already stands on it."""

    view: Any
    surfaces: list[Any]
    category: str
    caption: str
    on_it: list[str]


def _render(
    folder: Path, receptacle_id: str, surfaces: list[Any], compiled: Any, width: int, height: int
) -> Any:
    from holomj.jobs.refine_views import render_receptacle

    try:
        return render_receptacle(
            folder, receptacle_id, surfaces, width=width, height=height, compiled=compiled
        )
    except HolomjError as err:
        raise HolomjError(
            f"cannot render the receptacle to point at: {err.one_line()}",
            fix="pointing needs OpenGL (MUJOCO_GL=egl or osmesa); use --planner offline",
        ) from None


def _retrieve(
    ctx: Any, scene: SceneSpec, receptacle_id: str, name: str, number: int
) -> dict[str, Any]:
    """The asset for a named small object (as ``add_on`` retrieves); a reason for the model
    when there is none."""
    from holomj.edit.describe import describe
    from holomj.edit.small import category_words
    from holomj.edit.state import Refused, find
    from holomj.plan.new_kinds import kind_name

    receptacle = find(scene, receptacle_id)
    library = ctx.library
    meta = library.get(receptacle.asset).meta
    room_type = scene.room(receptacle.room).type if receptacle.room else "room"
    try:
        asked = describe(f"{name} on the {category_words(meta.category)}", room_type, ctx.seed)
    except Refused as err:
        raise LLMResponseError(f"{name!r}: {err.reason}; name a small object") from None
    if asked.placement != "object":
        raise LLMResponseError(
            f"{name!r} is not a small object ({asked.name} is a {asked.placement} object); "
            "name something that goes on it"
        )
    words = kind_name(name) or asked.description
    try:
        pick = ctx.retriever.choose(
            words,
            quantity=1,
            variance="same",
            rng=ctx.rng("pointing", number, "retrieve"),
            placement="object",
            category=asked.category,
        )[0]
    except (HolomjError, Refused) as err:
        why = err.one_line() if isinstance(err, HolomjError) else err.reason
        raise LLMResponseError(f"no asset for {name!r} ({why}); name another object") from None
    return {
        "asset": pick.asset_id,
        "category": asked.category,
        "how": getattr(pick, "how", "ranked"),
    }
