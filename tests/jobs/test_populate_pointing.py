"""Populate by pointing (:mod:`holomj.jobs.pointing`, ``populate_folder(..., instruction=...)``).

Fast tests: pixels to rays and back, rays onto stacked surfaces, the answers' checks. Slow tests
on a generated living room: the receptacle view's camera agrees with MuJoCo's depth image; a
scripted OpenAI-compatible server names objects and points at pixels (images sent as
image_url parts; a pixel off the surface, a piece of furniture and code are sent back) and the
objects land where it pointed; offline, the instruction's objects or the priors decide.
"""

from __future__ import annotations

import base64
import json
import shutil
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import Polygon, box

import holomj
from holomj.jobs.folder import open_library, read_scene
from holomj.jobs.populate import populate_folder
from holomj.library.store import AssetLibrary
from holomj.plan.llm_config import LLMConfig
from holomj.plan.llm_json import LLMResponseError
from holomj.refinement.pointing import PinholeCamera, hit_surface, parse_name, parse_pixel
from tests.plan.llm_replay import replay_server

TABLE = "living_room.coffee_table_0"


@dataclass(frozen=True)
class Surface:
    index: int
    height: float
    polygon: Polygon


def down_camera() -> PinholeCamera:
    """A camera 2 m above (1, 1, 0) looking straight down, +Y up in the image."""
    return PinholeCamera((1.0, 1.0, 2.0), (0.0, 0.0, -1.0), (0.0, 1.0, 0.0), 45.0, 400, 300)


def test_pixels_and_rays_agree() -> None:
    camera = down_camera()
    for point in [(1.0, 1.0, 0.0), (1.3, 0.8, 0.4), (0.4, 1.5, 0.75)]:
        u, v = camera.project(point)  # type: ignore[misc]
        origin, direction = camera.ray(u, v)
        t = (point[2] - origin[2]) / direction[2]
        assert np.allclose(origin + t * direction, point, atol=1e-9)
    u, v = camera.project((1.0, 1.0, 0.0))  # type: ignore[misc]
    assert (u, v) == pytest.approx((199.5, 149.5))
    assert camera.project((1.5, 1.0, 0.0))[0] > u  # +x to the right  # type: ignore[index]
    assert camera.project((1.0, 1.5, 0.0))[1] < v  # +y up  # type: ignore[index]
    assert camera.project((1.0, 1.0, 3.0)) is None  # behind the camera


def test_rays_hit_the_first_surface_inside_its_polygon() -> None:
    camera = down_camera()
    shelf = Surface(0, 0.3, box(0.5, 0.5, 1.5, 1.5))
    top = Surface(1, 0.8, box(0.8, 0.8, 1.2, 1.2))
    u, v = camera.project((1.0, 1.0, 0.8))  # type: ignore[misc]
    hit = hit_surface(camera, u, v, [shelf, top])
    assert hit.index == 1 and hit.point[2] == pytest.approx(0.8)
    u, v = camera.project((0.6, 0.6, 0.3))  # type: ignore[misc]
    assert hit_surface(camera, u, v, [shelf, top]).index == 0
    with pytest.raises(LLMResponseError, match="not on the receptacle's surface"):
        hit_surface(camera, 2, 2, [shelf, top])


def test_answers_are_checked() -> None:
    assert parse_name('{"object": "a red mug"}') == "a red mug"
    assert parse_name('{"done": true}') is None
    for bad, why in [
        ("a mug please", "not JSON"),
        ('{"object": "__import__(\'os\')"}', "looks like code"),
        ('{"object": ""}', "expected"),
        ('{"object": "' + "x" * 200 + '"}', "longer"),
    ]:
        with pytest.raises(LLMResponseError, match=why):
            parse_name(bad)
    assert parse_pixel('{"pixel": [10, 20.7]}', 400, 300) == (10, 20)
    for bad, why in [
        ('{"pixel": [400, 10]}', "outside the 400 x 300 image"),
        ('{"pixel": [-1, 10]}', "outside"),
        ('{"pixel": "center"}', "two numbers"),
        ('{"pixel": [1, 2, 3]}', "two numbers"),
    ]:
        with pytest.raises(LLMResponseError, match=why):
            parse_pixel(bad, 400, 300)


# --------------------------------------------------------------------------- a real scene


@pytest.fixture(scope="module")
def living_room(tmp_path_factory: pytest.TempPathFactory, default_library: AssetLibrary) -> Path:
    """A generated living room (tests populate copies)."""
    out = tmp_path_factory.mktemp("pointing") / "living_room"
    holomj.generate(
        "a living room with a sofa, a coffee table and a tv",
        out,
        seed=0,
        render=False,
        library=default_library,
    )
    return out


def table_surfaces(folder: Path) -> list:
    from holomj.physics.surfaces_world import world_surfaces

    scene = read_scene(folder)
    table = next(o for o in scene.objects if o.id == TABLE)
    return world_surfaces(table, open_library(folder).get(table.asset).meta)


@pytest.mark.slow
def test_the_view_camera_matches_mujocos_depth(living_room: Path) -> None:
    """The pixel rays of the receptacle view meet what MuJoCo drew at that pixel: where
    ``mj_ray`` along a pixel's ray meets the floor (exact geometry; meshes are hit on their
    hulls), the rendered depth agrees with it, over the whole image; and the centre of the
    table top hits the top surface at the depth drawn there."""
    import mujoco

    from holomj.jobs.refine_views import render_receptacle
    from holomj.jobs.render import load_scene_model
    from holomj.rendering.source import settled_qpos

    surfaces = table_surfaces(living_room)
    view = render_receptacle(living_room, TABLE, surfaces, depth=True)
    assert view.png[:8] == b"\x89PNG\r\n\x1a\n" and view.depth.shape == (300, 400)
    model = load_scene_model(living_room)
    data = mujoco.MjData(model)
    qpos = settled_qpos(model)
    if qpos is not None:
        data.qpos[:] = qpos
    mujoco.mj_forward(model, data)
    visible = np.array([1, 0, 1, 0, 0, 0], dtype=np.uint8)
    forward = np.asarray(view.camera.forward)
    geom = np.zeros(1, dtype=np.int32)
    compared = 0
    for u in (20, 110, 200, 290, 380):
        for v in (20, 85, 150, 215, 280):
            origin, direction = view.camera.ray(u, v)
            distance = mujoco.mj_ray(model, data, origin, direction, visible, 1, -1, geom)
            if distance < 0 or not model.geom(int(geom[0])).name.startswith("structure/"):
                continue
            along = view.depth[v, u] / float(direction @ forward)
            assert along == pytest.approx(distance, abs=0.01), (u, v)
            compared += 1
    assert compared >= 3
    top = max(surfaces, key=lambda s: s.height)
    centre = top.polygon.centroid
    u, v = view.camera.project((centre.x, centre.y, top.height))  # type: ignore[misc]
    hit = hit_surface(view.camera, int(u), int(v), surfaces)
    assert hit.index == top.index and hit.point[2] == pytest.approx(top.height)
    along = float((np.asarray(hit.point) - np.asarray(view.camera.position)) @ forward)
    assert view.depth[int(v), int(u)] == pytest.approx(along, abs=0.01)


@pytest.mark.slow
def test_llm_names_points_and_the_objects_land_there(
    living_room: Path, tmp_path: Path, default_library: AssetLibrary
) -> None:
    folder = tmp_path / "scene"
    shutil.copytree(living_room, folder)
    from holomj.jobs.refine_views import render_receptacle

    surfaces = table_surfaces(folder)
    camera = render_receptacle(folder, TABLE, surfaces).camera
    top = max(surfaces, key=lambda s: s.height)
    xmin, ymin, xmax, ymax = top.polygon.bounds
    spots = [(xmin + 0.25 * (xmax - xmin), ymin + 0.3 * (ymax - ymin))]
    spots.append((xmin + 0.75 * (xmax - xmin), ymin + 0.7 * (ymax - ymin)))
    pixels = [[int(c) for c in camera.project((x, y, top.height))] for x, y in spots]  # type: ignore[union-attr]
    replies = [
        {"content": '{"object": "a book"}'},
        {"content": '{"pixel": [2, 2]}'},  # off the table: sent back
        {"content": json.dumps({"pixel": pixels[0]})},
        {"content": '{"object": "a sofa"}'},  # not a small object: sent back
        {"content": "```python\nimport os\n```"},  # code: sent back
        {"content": '{"object": "an apple"}'},
        {"content": json.dumps({"pixel": pixels[1]})},
        {"content": '{"done": true}'},
    ]
    with replay_server(replies) as server:
        config = LLMConfig(base_url=server.base_url, model="vlm", max_retries=2, backoff_s=0.0)
        result = populate_folder(
            folder,
            TABLE,
            None,
            instruction="a book and a snack for a reading break",
            planner="llm",
            llm_config=config,
            library_path=default_library.root,
            count=3,
        )
    assert server.remaining == 0
    for request in server.requests:
        parts = request.messages[1]["content"]
        (image,) = [p for p in parts if p["type"] == "image_url"]
        data = image["image_url"]["url"].split(",", 1)
        assert data[0] == "data:image/png;base64"
        assert base64.b64decode(data[1])[:4] == b"\x89PNG"
    assert "not on the receptacle's surface" in server.requests[2].messages[-1]["content"]
    assert "not a small object" in server.requests[4].messages[-1]["content"]
    assert "code" in server.requests[5].messages[-1]["content"]
    assert result.placed == 2 and result.requested == 2
    report = result.report
    assert report.planner == "llm" and report.drawn_from == "llm pointing"
    assert report.pointing is not None and report.llm is not None
    placed = [r for r in report.pointing if r["status"] == "placed"]
    assert [r["name"] for r in placed] == ["a book", "an apple"]
    scene = read_scene(folder)
    for record, (x, y) in zip(placed, spots):
        assert record["distance_m"] <= 0.1
        obj = next(o for o in scene.objects if o.id == record["object_id"])
        assert obj.support == TABLE
        assert np.hypot(obj.position[0] - x, obj.position[1] - y) <= 0.12
    assert report.pointing[-1]["status"] == "done"
    assert report.llm["calls"] == 8 and report.llm["images_sent"] == 8
    assert report.llm["prompt_tokens"] == 800
    assert report.validation is not None and report.validation.ok


@pytest.mark.slow
def test_offline_the_instruction_or_the_priors_decide(
    living_room: Path,
    tmp_path: Path,
    default_library: AssetLibrary,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    folder = tmp_path / "scene"
    shutil.copytree(living_room, folder)
    result = populate_folder(
        folder,
        TABLE,
        None,
        instruction="a book and an apple",
        library_path=default_library.root,
    )
    assert result.report.drawn_from == "instruction"
    assert {r.name for r in result.report.requests} == {"book", "apple"}
    for name in ("HOLOMJ_LLM_BASE_URL", "OPENAI_BASE_URL", "HOLOMJ_LLM_MODEL"):
        monkeypatch.delenv(name, raising=False)
    again = populate_folder(
        folder,
        TABLE,
        None,
        instruction="something nice",
        planner="llm",
        library_path=default_library.root,
        count=2,
    )
    assert again.report.planner == "offline"
    assert again.report.notes is not None and "no LLM" in again.report.notes[0]
    assert again.report.drawn_from != "instruction"  # nothing named: the priors
    with pytest.raises(holomj.InputError, match="not both"):
        populate_folder(folder, TABLE, "mug", instruction="a mug")
