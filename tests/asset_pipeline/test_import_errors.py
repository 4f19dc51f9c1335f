"""Bad files are rejected with one-line FormatErrors naming the file; the CoACD fallback chain."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from asset_pipeline.decompose import CoacdParams
from asset_pipeline.importer import ImportOptions, import_asset
from holomj.errors import FormatError, HolomjError, SpecError
from tests.asset_pipeline.import_helpers import LOW, box_obj

TETRA = "v 0 0 0\nv {s} 0 0\nv 0 {s} 0\nv 0 0 {s}\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"


def _rejects(path: Path, match: str, **options) -> FormatError:
    with pytest.raises(FormatError, match=match) as info:
        import_asset(path, "bad", ImportOptions(coacd=LOW, **options))
    message = str(info.value)
    assert str(path) in message and "\n" not in message
    return info.value


def test_missing_file(tmp_path: Path) -> None:
    _rejects(tmp_path / "nope.glb", "not found")


def test_empty_file(tmp_path: Path) -> None:
    path = tmp_path / "empty.glb"
    path.write_bytes(b"")
    _rejects(path, "empty")


def test_truncated_glb(tmp_path: Path, shared_assets: Path) -> None:
    data = (shared_assets / "objects/bm_coffee_cup/coffee_cup.glb").read_bytes()
    path = tmp_path / "half.glb"
    path.write_bytes(data[: len(data) // 2])
    _rejects(path, "cannot parse")


def test_nan_vertex(tmp_path: Path) -> None:
    path = tmp_path / "nan.obj"
    path.write_text(TETRA.format(s=1).replace("v 0 0 1", "v 0 nan 1"))
    _rejects(path, "NaN")


def test_absurd_sizes(tmp_path: Path) -> None:
    huge = tmp_path / "huge.obj"
    huge.write_text(TETRA.format(s=100))
    _rejects(huge, "absurd size")
    tiny = tmp_path / "tiny.obj"
    tiny.write_text(TETRA.format(s=0.0001))
    _rejects(tiny, "absurd size")
    ok = tmp_path / "ok.obj"
    ok.write_text(TETRA.format(s=100))
    assert import_asset(ok, "ok", ImportOptions(size=(1, 1, 1), coacd=LOW)).bundle.meta.size == (
        pytest.approx((1.0, 1.0, 1.0))
    )


def test_too_many_faces_and_no_triangles(tmp_path: Path) -> None:
    path = tmp_path / "box.obj"
    path.write_text(box_obj())
    _rejects(path, "more than the limit", max_faces=10)
    points = tmp_path / "points.obj"
    points.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n")
    _rejects(points, "no triangles")


def test_unsupported_extension_and_bad_id(tmp_path: Path) -> None:
    path = tmp_path / "model.fbx"
    path.write_bytes(b"x")
    _rejects(path, "unsupported")
    good = tmp_path / "box.obj"
    good.write_text(box_obj())
    with pytest.raises(SpecError, match="asset id"):
        import_asset(good, "../evil", ImportOptions(coacd=LOW))


@settings(
    max_examples=50,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture],
)
@given(data=st.binary(min_size=0, max_size=600), suffix=st.sampled_from([".glb", ".obj", ".stl"]))
def test_random_bytes_only_raise_holomj_errors(tmp_path: Path, data: bytes, suffix: str) -> None:
    path = tmp_path / f"fuzz{suffix}"
    path.write_bytes(data)
    try:
        import_asset(path, "fuzz", ImportOptions(coacd=LOW))
    except HolomjError as err:
        assert "\n" not in str(err)


def test_coacd_timeout_falls_back_to_the_convex_hull(shared_assets: Path, tmp_path: Path) -> None:
    options = ImportOptions(category="mug", coacd=CoacdParams(timeout_s=0.01))
    imported = import_asset(shared_assets / "objects/bm_coffee_cup/coffee_cup.glb", "m", options)
    decomposition = imported.report["decomposition"]
    assert decomposition["method"] == "convex_hull"
    statuses = [(a["method"], a["status"]) for a in decomposition["attempts"]]
    assert statuses == [("coacd", "timeout"), ("coacd_coarse", "timeout"), ("convex_hull", "ok")]
    assert "did not finish" in decomposition["fallback_reason"]
    assert len(imported.bundle.meta.collision) == 1
    assert imported.report["quality"]["max_outward_deviation_m"] <= 0.003 + 1e-6
