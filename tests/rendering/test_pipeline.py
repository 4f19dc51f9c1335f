"""render_scene: options checked, the model left alone, the pose given, the plan, no disk I/O."""

from __future__ import annotations

import io

import mujoco
import numpy as np
import pytest
from PIL import Image

from holomj.errors import InputError
from holomj.mjcf.compiler import CompiledScene
from holomj.mjcf.geometry import look_at_quat
from holomj.rendering import RenderOptions, check_size, gl, parse_views, render_scene
from holomj.rendering.cameras import CameraPose, TopCamera
from holomj.rendering.source import prepare_scene, settled_qpos
from holomj.rendering.views import scene_option


def test_parse_views_checks_names_and_orders_them() -> None:
    assert parse_views("rooms, top") == ("top", "rooms")
    assert parse_views(["objects", "top", "top"]) == ("top", "objects")
    with pytest.raises(InputError, match=r"unknown view 'plan'.*top, rooms, objects"):
        parse_views("top,plan")
    with pytest.raises(InputError, match="no view"):
        parse_views(" , ")


@pytest.mark.parametrize(("width", "height"), [(0, 480), (640, 100_000), (8, 8), (-5, 10)])
def test_absurd_sizes_are_bad_input(width: int, height: int) -> None:
    with pytest.raises(InputError, match="out of range") as info:
        check_size(width, height)
    assert info.value.exit_code == 2


def test_options_round_trip_through_json() -> None:
    options = RenderOptions(("top", "objects"), 32, 24, depth=True)
    assert RenderOptions.from_dict(options.to_dict()) == options


def test_the_model_is_left_as_it_was(two_room_compiled: CompiledScene) -> None:
    model = two_room_compiled.model
    before = (model.vis.global_.offwidth, model.vis.global_.fovy, model.vis.global_.orthographic)
    options = RenderOptions(("top",), width=2000, height=24, shadows=False)
    render_scene(model, two_room_compiled.scene, options)
    after = (model.vis.global_.offwidth, model.vis.global_.fovy, model.vis.global_.orthographic)
    assert after == before


def test_qpos_poses_the_scene(two_room_compiled: CompiledScene) -> None:
    model = two_room_compiled.model
    qpos = model.qpos0.copy()
    address = model.jnt_qposadr[model.joint("crate/freejoint").id]
    qpos[address : address + 2] = (6.3, 4.3)  # the crate, moved into the far corner
    options = RenderOptions(("top",), width=160, height=120, segmentation=True)
    rendering = render_scene(model, two_room_compiled.scene, options, qpos=qpos)
    assert rendering.legend is not None and rendering.top is not None
    crate = next(e["label"] for e in rendering.legend["labels"] if e["name"] == "crate")
    top = rendering.top
    camera = TopCamera(tuple(top["centre"]), top["height_m"], 160, 120, 0.0)
    labels = np.asarray(Image.open(io.BytesIO(rendering.images["top_seg.png"])))
    u, v = (round(c) for c in camera.to_pixel(6.3, 4.3))
    assert labels[v, u] == crate
    u, v = (round(c) for c in camera.to_pixel(5.5, 2.5))  # where the scene puts it
    assert labels[v, u] != crate


def test_settled_qpos_reads_the_settled_keyframe(two_room_compiled: CompiledScene) -> None:
    assert settled_qpos(two_room_compiled.model) is None
    spec = two_room_compiled.spec.copy()
    qpos = two_room_compiled.model.qpos0.copy()
    qpos[0] += 0.5
    spec.add_key(name="settled", qpos=qpos.tolist())
    found = settled_qpos(spec.compile())
    assert found is not None and np.allclose(found, qpos)


def test_the_plan_is_drawn_on_the_top_view(two_room_compiled: CompiledScene) -> None:
    options = RenderOptions(("top",), width=48, height=32)
    rendering = render_scene(two_room_compiled.model, two_room_compiled.scene, options)
    assert sorted(rendering.images) == ["plan.png", "top.png"]
    width, height = Image.open(io.BytesIO(rendering.images["plan.png"])).size
    assert width == 48 and height > 32  # the legend strip goes below the view
    assert rendering.timings_s["total"] > 0 and rendering.backend in ("egl", "osmesa", "glfw")


def test_close_ups_need_something_resting_on_a_receptacle(
    two_room_compiled: CompiledScene,
) -> None:
    scene = two_room_compiled.scene
    bare = scene.model_copy(
        update={"objects": [o.model_copy(update={"support": None}) for o in scene.objects]}
    )
    options = RenderOptions(("objects",), width=32, height=24)
    rendering = render_scene(two_room_compiled.model, bare, options)
    assert rendering.views == [] and rendering.images == {}


def test_no_context_is_gl_unavailable(two_room_compiled: CompiledScene, monkeypatch) -> None:
    def no_context(*args, **kwargs):
        raise gl.GLUnavailable("EGL: no display", where="MUJOCO_GL=egl")

    monkeypatch.setattr(gl, "open_renderer", no_context)
    options = RenderOptions(("top",), width=32, height=24)
    with pytest.raises(gl.GLUnavailable, match="no display"):
        render_scene(two_room_compiled.model, two_room_compiled.scene, options)


def test_free_cameras_match_model_cameras(two_room_compiled: CompiledScene) -> None:
    """A view drawn with the free camera equals one drawn from a model camera at the pose."""
    poses = [
        CameraPose("top", (3.5, 2.5, 4.7), (3.5, 2.5, 0.0), 6.2, orthographic=True),
        CameraPose("room", (3.65, 2.65, 1.6), (2.0, 1.2, 0.4), 75.0),
        CameraPose("close", (3.84, 1.2, 1.97), (2.0, 1.2, 0.43), 45.0),
    ]
    spec = two_room_compiled.spec.copy()
    for pose in poses:
        spec.worldbody.add_camera(
            name=pose.name,
            pos=list(pose.position),
            quat=[1.0, 0.0, 0.0, 0.0]
            if pose.orthographic
            else look_at_quat(pose.position, pose.target),
            fovy=pose.fovy,
            proj=mujoco.mjtProjection(int(pose.orthographic)),
        )
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    rs = prepare_scene(two_room_compiled.model, two_room_compiled.scene, 64, 48)
    with mujoco.Renderer(rs.model, 48, 64) as free, mujoco.Renderer(model, 48, 64) as fixed:
        for pose in poses:
            option = scene_option(show_ceilings=not pose.orthographic)
            free.update_scene(rs.data, rs.aim(pose), option)
            fixed.update_scene(data, pose.name, option)
            difference = np.abs(free.render().astype(int) - fixed.render().astype(int))
            assert difference.mean() < 0.5, pose.name
