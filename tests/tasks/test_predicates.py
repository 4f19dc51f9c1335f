"""Success predicates on a generated kitchen: doing nothing is never success; a fridge door set
past the fraction is (and only once it has held); a mug teleported onto the sink counter and
settled is; an unknown id is refused with the ids the scene has."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest

from holomj.errors import InputError
from holomj.spec.tasks import ArticulationTask, NavigateTask, PickPlaceTask, PlaceGoal, Task
from holomj.tasks.predicates import SuccessCheck, success_check


@pytest.fixture(scope="module")
def scene(kitchen: Path) -> tuple[mujoco.MjModel, dict[str, Any]]:
    model = mujoco.MjModel.from_xml_path(str(kitchen / "scene.xml"))
    return model, json.loads((kitchen / "objects.json").read_text())


def _objects(record: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {o["id"]: o for o in record["objects"]}


def _first(record: dict[str, Any], category: str) -> dict[str, Any]:
    return next(o for o in record["objects"] if o["category"] == category)


def rollout(
    model: mujoco.MjModel,
    check: SuccessCheck,
    seconds: float,
    setup: Callable[[mujoco.MjData], None] | None = None,
    act: Callable[[mujoco.MjData], None] | None = None,
) -> bool:
    """Step the scene for ``seconds`` from its initial state (after ``setup``); whether the
    check reported success."""
    data = mujoco.MjData(model)
    if setup is not None:
        setup(data)
    mujoco.mj_forward(model, data)
    check.reset()
    for _ in range(round(seconds / model.opt.timestep)):
        if act is not None:
            act(data)
        mujoco.mj_step(model, data)
        if check.update(data):
            return True
    return False


def _open_task(record: dict[str, Any], kind: str = "open", fraction: float = 0.5) -> Task:
    fridge = _first(record, "fridge")
    joint = fridge["joints"][0]["name"]
    return ArticulationTask(kind=kind, id="t", object=fridge["id"], joint=joint, fraction=fraction)


def _set_joint(model: mujoco.MjModel, name: str, value: float) -> Callable[[mujoco.MjData], None]:
    adr = model.jnt_qposadr[model.joint(name).id]

    def setup(data: mujoco.MjData) -> None:
        data.qpos[adr] = value

    return setup


def _sink_goal(record: dict[str, Any]) -> PickPlaceTask:
    mug = _first(record, "mug")
    sink = _first(record, "sink_counter")
    return PickPlaceTask(id="p", goal=PlaceGoal(object=mug["id"], receptacle=sink["id"], surface=0))


def test_doing_nothing_is_not_success(scene) -> None:
    model, record = scene
    for task in (_open_task(record), _sink_goal(record)):
        assert not rollout(model, success_check(task, model, record), 1.5)


def test_a_fridge_door_set_open_is_success_once_it_has_held(scene) -> None:
    model, record = scene
    task = _open_task(record)
    joint = task.joint
    _, high = _objects(record)[task.object]["joints"][0]["range"]
    check = success_check(task, model, record)
    assert rollout(model, check, 1.5, _set_joint(model, joint, 0.7 * high))
    assert check.last.holds and check.last.distance == 0.0
    assert not rollout(model, check, 1.5, _set_joint(model, joint, 0.3 * high))
    assert check.last.distance > 0.1
    # the same door is closed (below 5 % of its range) when left alone, not when set open
    close = _open_task(record, "close", 0.05)
    assert rollout(model, success_check(close, model, record), 1.5)
    assert not rollout(
        model, success_check(close, model, record), 1.5, _set_joint(model, joint, 1.0)
    )


def test_holding_means_in_a_row(scene) -> None:
    model, record = scene
    task = _open_task(record)
    adr = model.jnt_qposadr[model.joint(task.joint).id]
    check = success_check(task, model, record)
    data = mujoco.MjData(model)
    data.qpos[adr] = 1.2
    mujoco.mj_forward(model, data)
    assert not check.update(data)  # it starts to hold now
    data.time += 0.6
    assert not check.update(data)
    data.qpos[adr] = 0.0  # closed again: the clock starts over
    data.time += 0.6
    assert not check.update(data)
    data.qpos[adr] = 1.2
    data.time += 0.1
    assert not check.update(data)
    data.time += 1.0
    assert check.update(data)


def test_a_mug_teleported_onto_the_sink_counter_is_placed(scene) -> None:
    model, record = scene
    task = _sink_goal(record)
    mug = _objects(record)[task.goal.object]
    surface = _objects(record)[task.goal.receptacle]["surfaces"][0]
    adr = model.jnt_qposadr[model.joint(mug["joint"]).id]
    cx, cy = np.mean(np.asarray(surface["polygon"]), axis=0)
    lift = mug["position"][2] - mug["aabb"]["min"][2]

    def teleport(data: mujoco.MjData) -> None:
        data.qpos[adr : adr + 3] = [cx, cy, surface["height"] + lift + 0.01]

    check = success_check(task, model, record)
    assert rollout(model, check, 3.0, teleport)

    def beside(data: mujoco.MjData) -> None:  # on the floor next to the counter: not placed
        teleport(data)
        data.qpos[adr + 2] = lift + 0.01
        data.qpos[adr] = model.stat.center[0]

    assert not rollout(model, success_check(task, model, record), 2.0, beside)


def test_random_joint_pushes_are_never_success(scene) -> None:
    model, record = scene
    rng = np.random.default_rng(0)
    tasks = [_open_task(record), _sink_goal(record)]

    def act(data: mujoco.MjData) -> None:
        data.qfrc_applied[:] = 0.0
        robot = [j for j in range(model.njnt) if model.joint(j).name.startswith("robot/")]
        for j in robot:
            data.qfrc_applied[model.jnt_dofadr[j]] = rng.normal(0.0, 5.0)

    for task in tasks:
        for _ in range(3):
            assert not rollout(model, success_check(task, model, record), 1.0, act=act)


def test_navigation_reads_the_robots_base(scene) -> None:
    model, record = scene
    room = record["robot"]["room"]
    assert rollout(model, success_check(NavigateTask(id="n", room=room), model, record), 0.01)
    far = max(
        record["objects"],
        key=lambda o: np.hypot(
            o["position"][0] - record["robot"]["position"][0],
            o["position"][1] - record["robot"]["position"][1],
        ),
    )
    task = NavigateTask(id="n", object=far["id"], radius_m=0.5)
    assert not rollout(model, success_check(task, model, record), 0.01)


def test_unknown_ids_are_refused_with_what_the_scene_has(scene) -> None:
    model, record = scene
    bad = ArticulationTask(kind="open", id="t", object="nope", joint="x")
    with pytest.raises(InputError, match=r"no object 'nope'.*use one of"):
        success_check(bad, model, record)
    fridge = _first(record, "fridge")
    bad = ArticulationTask(kind="open", id="t", object=fridge["id"], joint="x")
    with pytest.raises(InputError, match="has no joint 'x'"):
        success_check(bad, model, record)
    bad_room = NavigateTask(id="n", room="attic")
    with pytest.raises(InputError, match="no room 'attic'"):
        success_check(bad_room, model, record)
