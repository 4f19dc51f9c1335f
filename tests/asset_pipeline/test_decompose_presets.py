"""CoACD presets: default is the cheap-but-close setting, fine keeps CoACD's search, the
coarse fallback is cheaper than what it falls back from; attempts record their CPU time."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest
import trimesh

from asset_pipeline.decompose import CoacdParams, decompose
from asset_pipeline.manage import PRESETS, coacd_params
from holomj.errors import InputError

SEARCH = ("preprocess_resolution", "resolution", "mcts_nodes", "mcts_iterations", "mcts_max_depth")


def _cost_not_above(cheap: CoacdParams, dear: CoacdParams) -> bool:
    """Whether every cost knob of ``cheap`` is at most ``dear``'s (its thresholds at least)."""
    return all(
        cheap.threshold_for(mode) >= dear.threshold_for(mode) for mode in ("on", "off")
    ) and all(getattr(cheap, k) <= getattr(dear, k) for k in SEARCH)


def test_default_preset_is_the_dataclass_default_and_cheaper_than_fine() -> None:
    default, fine, fast = coacd_params("default"), coacd_params("fine"), coacd_params("fast")
    assert default == CoacdParams()
    assert _cost_not_above(default, fine) and default != fine
    assert _cost_not_above(fast, default)
    # fine keeps CoACD's own search (preprocessing at 50, 2000 samples, 20 nodes) and more time.
    assert (fine.preprocess_resolution, fine.resolution, fine.mcts_nodes) == (50, 2000, 20)
    assert fine.max_convex_hull > default.max_convex_hull and fine.timeout_s > default.timeout_s
    assert set(PRESETS) == {"fast", "default", "fine"}
    # Watertight meshes keep CoACD's threshold; remeshed ones get one as coarse as the remesh.
    assert default.threshold_for("off") == 0.05
    assert default.threshold_for("on") == default.preprocessed_threshold == 0.1
    assert default.run_kwargs("on")["threshold"] == 0.1 and "preprocessed_threshold" not in (
        default.run_kwargs("off")
    )
    # A threshold asked for holds for every mesh.
    asked = coacd_params("default", threshold=0.2)
    assert asked.threshold_for("on") == asked.threshold_for("off") == 0.2
    with pytest.raises(InputError, match="unknown preset"):
        coacd_params("ultra")


@pytest.mark.parametrize("preset", sorted(PRESETS))
def test_coarse_fallback_is_never_dearer(preset: str) -> None:
    params = coacd_params(preset)
    coarse = params.coarse()
    assert _cost_not_above(coarse, params)
    assert coarse.max_convex_hull <= max(params.max_convex_hull, 8)
    assert coarse.coarse() == coarse  # a second coarsening changes nothing


def test_attempts_record_wall_and_cpu_seconds(tmp_path: Path) -> None:
    # An L-shaped block is not convex: CoACD runs (with the fast settings).
    a = trimesh.creation.box(extents=(0.2, 0.05, 0.05))
    b = trimesh.creation.box(extents=(0.05, 0.05, 0.15))
    b.apply_translation((-0.075, 0, 0.1))
    mesh = trimesh.util.concatenate([a, b])
    mesh.merge_vertices()
    params = dataclasses.replace(coacd_params("fast"), timeout_s=60.0)
    result = decompose(mesh, params, manifold=False)
    (attempt,) = [a for a in result.attempts if a["method"] == "coacd"]
    assert attempt["status"] == "ok"
    assert attempt["seconds"] > 0 and attempt["cpu_seconds"] > 0
    # The child alone is counted: no more CPU than its wall time on a few cores.
    assert attempt["cpu_seconds"] <= attempt["seconds"] * 4 + 0.5
    assert attempt["params"]["threshold"] == params.threshold
