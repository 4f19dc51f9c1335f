"""Benchmark: headless rendering speed at 640x480 for a 4-room scene, with and without shadows.

Frames per second of the top-down view and of the room views (update_scene + render + read
back), measured on whatever OpenGL the process gets (Mesa's llvmpipe on a CPU-only machine,
the GPU driver where there is one); plus the wall time of a whole ``render_folder``. Writes JSON::

    python scripts/bench_render.py --out bench_results/render.json [--frames 20]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from bench_scenes import grid_house  # sibling module in scripts/

from asset_pipeline.default_library import ensure_default_library
from holomj.jobs.folder import read_scene, write_scene_folder
from holomj.jobs.render import load_scene_model, render_folder
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.rendering import gl
from holomj.rendering.cameras import CameraPose, room_camera, top_camera
from holomj.rendering.source import RenderScene, prepare_scene, settled_qpos
from holomj.rendering.view_plan import house_bounds
from holomj.rendering.views import scene_option


def _fps(rs: RenderScene, renderer: Any, pose: CameraPose, top: bool, frames: int) -> float:
    option = scene_option(show_ceilings=not top)
    camera = rs.aim(pose)
    renderer.update_scene(rs.data, camera=camera, scene_option=option)
    renderer.render()  # warm-up: shaders, textures, shadow map
    start = time.perf_counter()
    for _ in range(frames):
        renderer.update_scene(rs.data, camera=camera, scene_option=option)
        renderer.render()
    return frames / (time.perf_counter() - start)


def _cpu_name() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("bench_results/render.json"))
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--objects", type=int, default=120, help="120 fill 4 rooms of 6 m")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    args = parser.parse_args()
    import mujoco  # after holomj, which picks the headless backend (MUJOCO_GL=egl)

    library = AssetLibrary.open(ensure_default_library())
    scene = grid_house(library, args.objects)
    with tempfile.TemporaryDirectory() as tmp:
        out = write_scene_folder(compile_scene(scene, library), Path(tmp) / "house")
        scene = read_scene(out)
        model = load_scene_model(out)
        rs = prepare_scene(model, scene, args.width, args.height, qpos=settled_qpos(model))
        top = top_camera(house_bounds(scene), args.width, args.height, scene.wall_height)
        top_pose = top.pose("render/top")
        masses = [m for m in (rs.mass(o.id) for o in scene.objects) if m is not None]
        aspect = args.width / args.height
        room_poses = [
            room_camera(f"render/room/{room.id}", room.polygon, masses, scene.wall_height, aspect)
            for room in scene.rooms
        ]
        results: dict[str, dict[str, float]] = {}
        with gl.open_renderer(rs.model, args.width, args.height) as renderer:
            renderer_name = gl.renderer_name()
            for shadows in (True, False):
                renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = shadows
                top_fps = _fps(rs, renderer, top_pose, True, args.frames)
                room_fps = [_fps(rs, renderer, pose, False, args.frames) for pose in room_poses]
                results["shadows" if shadows else "no_shadows"] = {
                    "top_fps": round(top_fps, 2),
                    "room_fps_median": round(statistics.median(room_fps), 2),
                    "room_fps_min": round(min(room_fps), 2),
                }
        folder_s = {}
        for shadows in (True, False):
            start = time.perf_counter()
            summary = render_folder(
                out, views=("top", "rooms"), width=args.width, height=args.height, shadows=shadows
            )
            folder_s["shadows" if shadows else "no_shadows"] = round(time.perf_counter() - start, 3)
        model = rs.model
    result = {
        "benchmark": "render",
        "width": args.width,
        "height": args.height,
        "rooms": len(scene.rooms),
        "objects": len(scene.objects),
        "geoms": int(model.ngeom),
        "frames_per_measure": args.frames,
        "fps": results,
        "render_folder_s": folder_s,
        "render_folder_images": len([f for f in summary.files if f.endswith(".png")]),
        "backend": gl.current_backend(),
        "gl_renderer": renderer_name,
        "cpu": _cpu_name(),
        "cpu_count": os.cpu_count(),
        "mujoco": mujoco.__version__,
        "python": platform.python_version(),
        "machine": platform.machine(),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps(result, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
