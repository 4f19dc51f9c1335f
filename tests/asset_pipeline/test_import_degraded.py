"""A fallback decomposition is a visible warning, marked degraded, and not cached unless accepted.

CoACD is made unavailable honestly: the child process that runs it (``python -m
asset_pipeline.decompose``) inherits ``PYTHONPATH``, and a ``coacd`` package placed first on it
fails to import, so the child exits with an ImportError as it would without CoACD installed.
A timeout comes from ``--timeout 0.01``: the child cannot even start in 10 ms.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
import trimesh
from typer.testing import CliRunner

from asset_pipeline.decompose import degraded_reason
from asset_pipeline.import_cache import CACHE_DIR, PENDING_DIR
from asset_pipeline.import_plan import plan_jobs
from asset_pipeline.importer import ImportOptions
from asset_pipeline.library_writer import write_library
from asset_pipeline.manage import coacd_params, run_imports
from holomj.cli import app
from holomj.library import AssetLibrary

MISSING = "CoACD unavailable (ModuleNotFoundError: No module named 'coacd')"


@pytest.fixture
def ring(tmp_path: Path) -> Path:
    """A small watertight ring: one non-convex body, so CoACD must run (about 2 s, fast)."""
    folder = tmp_path / "meshes"
    folder.mkdir()
    mesh = trimesh.creation.annulus(r_min=0.03, r_max=0.05, height=0.03, sections=24)
    path = folder / "ring.obj"
    mesh.export(path)
    return path


@pytest.fixture
def no_coacd(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Child processes find a ``coacd`` that cannot be imported (as if it were not installed)."""
    shadow = tmp_path / "shadow"
    (shadow / "coacd").mkdir(parents=True)
    (shadow / "coacd" / "__init__.py").write_text(
        "raise ModuleNotFoundError(\"No module named 'coacd'\")\n"
    )
    paths = [str(shadow), os.environ.get("PYTHONPATH", "")]
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(p for p in paths if p))


def _import(ring: Path, library: Path, *extra: str) -> tuple[int, str]:
    """Run ``holomj assets import`` on ``ring`` (fast preset, no thumbnails)."""
    args = ["assets", "import", str(ring), "--library", str(library), "--preset", "fast"]
    result = CliRunner().invoke(app, [*args, "--no-thumbnails", *extra])
    return result.exit_code, result.stdout


def _derivation(library: Path, asset_id: str = "ring") -> dict:
    root = AssetLibrary.open(library).get(asset_id).root
    return json.loads((root / "derivation.json").read_text())


def _pending(library: Path) -> list[Path]:
    folder = library / CACHE_DIR / PENDING_DIR
    return sorted(folder.iterdir()) if folder.is_dir() else []


def test_missing_coacd_warns_marks_degraded_and_is_retried(
    ring: Path, tmp_path: Path, no_coacd: None, monkeypatch: pytest.MonkeyPatch
) -> None:
    library = tmp_path / "lib"
    code, out = _import(ring, library)
    assert code == 0, out
    assert "ok (degraded)" in out
    assert f"warning: ring: ok (degraded: {MISSING}; single convex hull), 1 hull" in out
    assert "not cached: the next import retries CoACD" in out
    assert "1 imported, 1 degraded, 0 failed" in out

    derivation = _derivation(library)
    assert derivation["degraded"] is True
    assert derivation["degraded_reason"] == f"{MISSING}; single convex hull"
    assert derivation["fallback_accepted"] is False
    assert derivation["decomposition"]["method"] == "convex_hull"
    assert f"degraded decomposition: {MISSING}; single convex hull" in derivation["warnings"]
    key = derivation["cache_key"]
    assert not (library / CACHE_DIR / key).exists()  # not cached as final
    assert _pending(library) == []  # the pending copy went away after the commit

    listed = CliRunner().invoke(app, ["assets", "list", "--library", str(library), "--json"])
    assert {r["id"]: r["degraded"] for r in json.loads(listed.stdout)} == {
        "builtin:box": False,
        "ring": True,
    }

    monkeypatch.undo()  # CoACD is back: the same file and options run it again
    code, out = _import(ring, library, "--json")
    summary = json.loads(out)
    assert code == 0 and summary["succeeded"] == 1 and summary["degraded"] == 0
    assert summary["outcomes"][0]["cached"] is False
    assert summary["outcomes"][0]["degraded"] is False
    derivation = _derivation(library)
    assert derivation["cache_key"] == key
    assert derivation["degraded"] is False and derivation["degraded_reason"] is None
    assert derivation["decomposition"]["method"] == "coacd"
    assert (library / CACHE_DIR / key / "asset.json").is_file()
    code, out = _import(ring, library, "--json")
    assert json.loads(out)["outcomes"][0]["cached"] is True


def test_timeout_is_cached_only_with_accept_fallback(ring: Path, tmp_path: Path) -> None:
    library = tmp_path / "lib"
    timeout = ("--timeout", "0.01", "--json")
    reason = "CoACD timed out after 0.01 s; single convex hull"

    code, out = _import(ring, library, *timeout, "--accept-fallback")
    summary = json.loads(out)
    assert code == 0 and summary["degraded"] == 1
    first = summary["outcomes"][0]
    assert (first["cached"], first["degraded"], first["degraded_reason"]) == (False, True, reason)
    entry = library / CACHE_DIR / first["cache_key"] / "derivation.json"
    cached = json.loads(entry.read_text())
    assert cached["degraded"] is True and cached["fallback_accepted"] is True

    code, out = _import(ring, library, *timeout, "--accept-fallback")
    again = json.loads(out)["outcomes"][0]
    assert code == 0 and again["cached"] is True
    assert again["degraded"] is True and again["degraded_reason"] == reason

    code, out = _import(ring, library, *timeout, "--strict")
    retried = json.loads(out)["outcomes"][0]
    assert code == 1  # --strict: a degraded import fails the command (the asset is still added)
    assert retried["cached"] is False and retried["degraded"] is True  # no flag: CoACD again
    assert _derivation(library)["degraded"] is True
    assert json.loads(entry.read_text())["fallback_accepted"] is True  # the accepted entry stays
    assert _pending(library) == []


def test_degraded_results_cross_worker_processes(
    ring: Path, tmp_path: Path, no_coacd: None
) -> None:
    library = write_library(tmp_path / "lib", "lib", [])
    jobs = plan_jobs([ring, ring])  # the same file twice: one cache key, two pending folders
    options = ImportOptions(coacd=coacd_params("fast"))
    summary = run_imports(jobs, library, options, workers=2, thumbnails=False)
    assert sorted((o.asset_id, o.ok, o.degraded) for o in summary.outcomes) == [
        ("ring", True, True),
        ("ring-2", True, True),
    ]
    assert summary.to_dict()["degraded"] == 2
    assert all(_derivation(library, i)["degraded"] for i in ("ring", "ring-2"))
    assert not (library / CACHE_DIR / summary.outcomes[0].cache_key).exists()
    assert _pending(library) == []


def test_convex_mesh_is_not_degraded(tmp_path: Path) -> None:
    box = tmp_path / "box.obj"
    trimesh.creation.box(extents=(0.2, 0.1, 0.05)).export(box)
    library = write_library(tmp_path / "lib", "lib", [])
    options = ImportOptions(coacd=coacd_params("fast"))
    summary = run_imports(plan_jobs([box]), library, options, thumbnails=False)
    assert summary.outcomes[0].ok and not summary.outcomes[0].degraded
    derivation = _derivation(library, "box")
    assert derivation["degraded"] is False and derivation["degraded_reason"] is None
    assert (library / CACHE_DIR / derivation["cache_key"]).is_dir()


def test_degraded_reason_names_each_failure_once() -> None:
    def timeout(method: str) -> dict:
        return {"method": method, "status": "timeout", "params": {"timeout_s": 60.0}}

    crash = {"method": "coacd_coarse", "status": "error", "reason": "CoACD exited with code -11"}
    skipped = {"method": "coacd_coarse", "status": "skipped", "reason": "settings already coarse"}
    ok = {"method": "coacd", "status": "ok"}
    assert degraded_reason([ok], "coacd") is None
    assert degraded_reason([skipped, ok], "coacd") is None
    coarse = [timeout("coacd"), {**ok, "method": "coacd_coarse"}]
    assert degraded_reason(coarse, "coacd_coarse") == (
        "CoACD timed out after 60 s; coarser CoACD settings"
    )
    both = [timeout("coacd"), timeout("coacd_coarse"), {"method": "convex_hull", "status": "ok"}]
    assert degraded_reason(both, "convex_hull") == "CoACD timed out after 60 s; single convex hull"
    mixed = [timeout("coacd"), crash, {"method": "convex_hull", "status": "ok"}]
    assert degraded_reason(mixed, "convex_hull") == (
        "CoACD timed out after 60 s; CoACD exited with code -11; single convex hull"
    )
