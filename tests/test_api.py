"""The Python API as a user meets it: ``import holomj`` only, light, and the jobs end to end."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

HEAVY = ("torch", "ortools", "coacd", "mujoco", "sentence_transformers", "trimesh", "OpenGL")


def _fresh_python(code: str) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k != "MUJOCO_GL"}
    return subprocess.run(
        [sys.executable, "-X", "importtime", "-c", code],
        capture_output=True,
        text=True,
        check=True,
        env=env,
    )


def test_import_holomj_is_light_and_has_no_side_effects() -> None:
    code = (
        "import os, sys, json, holomj\n"
        f"heavy = [m for m in {HEAVY!r} if m in sys.modules]\n"
        "print(json.dumps({'heavy': heavy, 'gl': os.environ.get('MUJOCO_GL'),"
        " 'api': sorted(holomj.__all__)}))\n"
    )
    result = _fresh_python(code)
    facts = json.loads(result.stdout)
    assert facts["heavy"] == []
    assert facts["gl"] is None  # MUJOCO_GL is the user's to set
    assert {"generate", "compile", "validate", "render", "Scene", "AssetLibrary"} <= set(
        facts["api"]
    )
    # -X importtime: cumulative microseconds of the top-level 'holomj' import
    total = [
        int(line.split("|")[1])
        for line in result.stderr.splitlines()
        if line.startswith("import time:") and line.rstrip().endswith("| holomj")
    ]
    assert total and total[0] < 300_000, result.stderr[-2000:]


def test_unknown_attribute_is_an_attribute_error() -> None:
    import holomj

    with pytest.raises(AttributeError, match="no attribute 'frobnicate'"):
        holomj.frobnicate  # noqa: B018


@pytest.mark.slow
def test_generate_load_validate_render_from_python(tmp_path: Path, default_library) -> None:
    import holomj

    out = tmp_path / "kitchen"
    result = holomj.generate(
        "a small kitchen", out, seed=1, library=default_library.root, render=False
    )
    assert result.folder == out and result.report.ok and result.ok
    assert {"plan", "retrieve", "layout", "validate", "export"} <= set(result.timings)

    scene = holomj.Scene.load(out)
    assert scene.rooms and len(scene.objects) == len(scene.spec.objects)
    fridge = [o for o in scene.objects if o.category == "fridge"]
    assert fridge and fridge[0].room == scene.rooms[0].id
    assert len(fridge[0].pose.quat) == 4 and fridge[0].size[2] > 1.0
    assert scene.report is not None and scene.report.ok

    report = holomj.validate(out, monitor_s=1.0, sleep=True)
    assert report.ok and {o.name for o in report.objects} == {o.id for o in scene.objects}

    summary = holomj.render(out, width=160, height=120, views=["top"])
    assert (out / "renders" / "top.png").is_file() and summary.files
    assert (out / "report.html").is_file()

    with pytest.raises(holomj.HolomjError, match="not a holomj scene folder"):
        holomj.Scene.load(tmp_path)
    with pytest.raises(holomj.InputError):
        scene.object("no_such_object")


def test_default_library_is_built_on_first_use(default_library) -> None:
    import holomj

    library = holomj.AssetLibrary.default()
    assert library.root == default_library.root and len(library.ids()) > 50
