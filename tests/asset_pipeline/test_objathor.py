"""objathor directories -> library assets: layout, frames, metadata, colliders, tolerance.

The directories are built from shared meshes by :mod:`tests.asset_pipeline.objathor_data` in
objathor's own format (gzip pickle of the mesh dict, Unity frame, albedo.jpg, colliders).
"""

from __future__ import annotations

import gzip
import json
import os
import pickle
import shutil
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from asset_pipeline.objathor import (
    load_pickle,
    parse_annotation,
    plan_objathor,
    read_annotation_file,
    read_mesh,
    unity_to_asset,
)
from asset_pipeline.objathor_import import ObjathorOptions
from holomj.errors import FormatError, InputError
from holomj.jobs.assets import ImportRun
from holomj.jobs.objathor import import_objathor, parse_uids
from holomj.library import AssetLibrary
from holomj.spec.assets import PLACEMENTS
from tests.asset_pipeline.objathor_data import (
    BOX_UID,
    CLOCK_UID,
    DESK_UID,
    SPECS,
    asset_mesh,
    build_objathor_dir,
    mesh_dict,
    write_pickle,
)


@pytest.fixture(scope="module")
def shared(request: pytest.FixtureRequest) -> Path:
    return request.getfixturevalue("shared_assets")


@pytest.fixture(scope="module")
def imported(tmp_path_factory: pytest.TempPathFactory, shared: Path):
    """Three assets (desk, box, clock) imported with their shipped colliders."""
    root = tmp_path_factory.mktemp("objathor")
    meshes = build_objathor_dir(root / "dir", shared)
    result = import_objathor(root / "dir", library=root / "lib", run=ImportRun(thumbnails=False))
    return root, meshes, result


def _derivation(library: AssetLibrary, uid: str) -> dict:
    return json.loads((library.get(uid).root / "derivation.json").read_text())


def _obj_vertices(path: Path) -> np.ndarray:
    rows = [line.split()[1:4] for line in path.read_text().splitlines() if line.startswith("v ")]
    return np.asarray(rows, dtype=np.float64)


def _same_points(a: np.ndarray, b: np.ndarray, tol: float = 2e-6) -> bool:
    """Every point of ``a`` is within ``tol`` of a point of ``b`` and the other way round."""
    from scipy.spatial import cKDTree

    return bool((cKDTree(b).query(a)[0] <= tol).all() and (cKDTree(a).query(b)[0] <= tol).all())


def test_ids_are_uids_and_every_asset_imports(imported) -> None:
    root, _, result = imported
    summary = result.summary
    assert [o.asset_id for o in summary.outcomes] == sorted([DESK_UID, BOX_UID, CLOCK_UID])
    assert not summary.failed and not summary.degraded
    library = AssetLibrary.open(root / "lib")
    assert {DESK_UID, BOX_UID, CLOCK_UID} <= set(library.ids())


def test_metadata_from_annotations(imported) -> None:
    root, _, _ = imported
    library = AssetLibrary.open(root / "lib")
    desk, box, clock = (library.get(u).meta for u in (DESK_UID, BOX_UID, CLOCK_UID))
    assert (desk.category, box.category, clock.category) == ("desk", "box", "clock")
    assert desk.description == "A plain wooden writing desk with four legs."
    assert box.description == "A closed brown cardboard box."  # description_auto
    assert desk.placement == ["floor"]
    assert box.placement == ["floor", "object"]
    assert clock.placement == ["wall"]
    assert (desk.mass, box.mass, clock.mass) == pytest.approx((25.0, 0.4, 1.2))
    assert desk.license == "objaverse/sketchfab: by" and desk.attribution == "Tester, u:1"
    assert desk.surfaces, "a receptacle desk offers its top"
    assert desk.surfaces[-1].height == pytest.approx(0.75, abs=0.02)
    assert clock.surfaces == []  # receptacle: false -> nothing is placed on it
    assert all(m.visual[0].texture for m in (desk, box, clock))  # albedo.jpg, as PNG
    derivation = _derivation(library, DESK_UID)
    assert derivation["decomposition"]["method"] == "shipped"
    assert derivation["objathor"]["receptacle"] is True
    assert derivation["objathor"]["size_check"]["largest_difference_m"] == pytest.approx(
        0, abs=1e-5
    )
    assert derivation["physical"]["mass_source"] == "annotation"


def test_size_and_axes_round_trip(imported) -> None:
    """The asset's geometry is the mesh objathor stored, back in the asset frame: Unity +z is
    the front (+X), Unity y is up (+Z), and the reflection keeps faces outward."""
    root, meshes, _ = imported
    library = AssetLibrary.open(root / "lib")
    for uid, mesh in meshes.items():
        asset = library.get(uid)
        assert asset.meta.size == pytest.approx(tuple(mesh.size), abs=2e-6)
        visual = _obj_vertices(asset.root / asset.meta.visual[0].mesh)
        assert _same_points(visual, mesh.vertices)
        derivation = _derivation(library, uid)
        assert derivation["repairs"]["bodies_inverted"] == 0
        assert derivation["repairs"]["faces_flipped"] == 0
    desk = library.get(DESK_UID).meta
    assert desk.size == pytest.approx((0.5, 1.0, 0.75), abs=1e-5)  # depth along the front


def test_conversion_matrix() -> None:
    m = unity_to_asset(0.0)
    assert m @ [0, 0, 1] == pytest.approx([1, 0, 0])  # Unity front +z -> +X
    assert m @ [0, 1, 0] == pytest.approx([0, 0, 1])  # Unity up +y -> +Z
    assert m @ [1, 0, 0] == pytest.approx([0, -1, 0])  # Unity right +x -> -Y (a reflection)
    assert np.linalg.det(m) == pytest.approx(-1.0)
    # Unity turns clockwise seen from above: yRotOffset 90 takes the front (+z) to +x (right)
    assert unity_to_asset(90.0) @ [0, 0, 1] == pytest.approx([0, -1, 0])


def test_y_rot_offset_is_applied(tmp_path: Path, shared: Path) -> None:
    """THOR turns the stored mesh by yRotOffset: the asset must come out as THOR shows it."""
    meshes = build_objathor_dir(tmp_path / "dir", shared, (DESK_UID,), y_rot_offset_deg=30.0)
    result = import_objathor(
        tmp_path / "dir", library=tmp_path / "lib", run=ImportRun(thumbnails=False)
    )
    assert not result.summary.failed
    asset = AssetLibrary.open(tmp_path / "lib").get(DESK_UID)
    assert asset.meta.size == pytest.approx((0.5, 1.0, 0.75), abs=1e-5)
    assert _same_points(_obj_vertices(asset.root / "visual_0.obj"), meshes[DESK_UID].vertices)


def test_reimport_is_cached_and_identical(imported) -> None:
    root, _, _ = imported
    library = AssetLibrary.open(root / "lib")
    before = (library.get(DESK_UID).root / "asset.json").read_bytes()
    again = import_objathor(
        root / "dir", library=root / "lib", uids=[DESK_UID], run=ImportRun(thumbnails=False)
    )
    (outcome,) = again.summary.outcomes
    assert outcome.ok and outcome.cached
    assert "replaces" in (outcome.id_note or "")
    after = AssetLibrary.open(root / "lib").get(DESK_UID)
    assert (after.root / "asset.json").read_bytes() == before


def test_parallel_workers(tmp_path: Path, shared: Path) -> None:
    build_objathor_dir(tmp_path / "dir", shared, (BOX_UID, CLOCK_UID))
    result = import_objathor(
        tmp_path / "dir", library=tmp_path / "lib", run=ImportRun(workers=2, thumbnails=False)
    )
    assert [o.ok for o in result.summary.outcomes] == [True, True]
    assert {BOX_UID, CLOCK_UID} <= set(AssetLibrary.open(tmp_path / "lib").ids())


def test_coacd_colliders(tmp_path: Path, shared: Path) -> None:
    build_objathor_dir(tmp_path / "dir", shared, (BOX_UID,))
    result = import_objathor(
        tmp_path / "dir",
        library=tmp_path / "lib",
        colliders="coacd",
        run=ImportRun(preset="fast", thumbnails=False),
    )
    (outcome,) = result.summary.outcomes
    assert outcome.ok, outcome.error
    derivation = _derivation(AssetLibrary.open(tmp_path / "lib"), BOX_UID)
    assert derivation["decomposition"]["method"] != "shipped"
    assert derivation["decomposition"]["colliders_option"] == "coacd"


# -- tolerance -------------------------------------------------------------------------------
def _one_asset(tmp_path: Path, shared: Path, uid: str = BOX_UID) -> Path:
    build_objathor_dir(tmp_path / "dir", shared, (uid,))
    return tmp_path / "dir" / "assets" / uid


def test_missing_texture_is_a_warning(tmp_path: Path, shared: Path) -> None:
    folder = _one_asset(tmp_path, shared)
    (folder / "albedo.jpg").unlink()
    result = import_objathor(
        tmp_path / "dir", library=tmp_path / "lib", run=ImportRun(thumbnails=False)
    )
    assert result.summary.outcomes[0].ok
    asset = AssetLibrary.open(tmp_path / "lib").get(BOX_UID)
    assert asset.meta.visual[0].texture is None
    warnings = _derivation(AssetLibrary.open(tmp_path / "lib"), BOX_UID)["warnings"]
    assert any("no albedo texture" in w for w in warnings)


def test_missing_colliders_fall_back_to_coacd(tmp_path: Path, shared: Path) -> None:
    folder = _one_asset(tmp_path, shared)
    mesh = asset_mesh(shared, SPECS[BOX_UID][0], SPECS[BOX_UID][1])
    write_pickle(folder / f"{BOX_UID}.pkl.gz", mesh_dict(mesh, BOX_UID, colliders=False))
    result = import_objathor(
        tmp_path / "dir", library=tmp_path / "lib", run=ImportRun(preset="fast", thumbnails=False)
    )
    assert result.summary.outcomes[0].ok
    derivation = _derivation(AssetLibrary.open(tmp_path / "lib"), BOX_UID)
    assert derivation["decomposition"]["method"] != "shipped"
    assert any("no shipped colliders" in w for w in derivation["warnings"])


def test_corrupt_pickle_fails_naming_the_file(tmp_path: Path, shared: Path) -> None:
    folder = _one_asset(tmp_path, shared)
    path = folder / f"{BOX_UID}.pkl.gz"
    path.write_bytes(gzip.compress(b"\x80\x04this is not a pickle"))
    with pytest.raises(FormatError, match="corrupt pickle") as err:
        read_mesh(path)
    assert str(path) in str(err.value)
    result = import_objathor(
        tmp_path / "dir", library=tmp_path / "lib", run=ImportRun(thumbnails=False)
    )
    (outcome,) = result.summary.outcomes
    assert not outcome.ok and str(path) in (outcome.error or "")
    path.write_bytes(b"\x1f\x8b\x08\x00garbage")  # broken gzip stream
    with pytest.raises(FormatError, match=str(path)):
        read_mesh(path)


class _Evil:
    def __reduce__(self):
        return (os.system, ("touch pwned-by-pickle",))


def test_pickle_naming_code_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "x.pkl.gz"
    write_pickle(path, {"vertices": [], "payload": _Evil()})
    with pytest.raises(FormatError, match="unsafe pickle refused") as err:
        load_pickle(path)
    assert str(path) in str(err.value)
    assert not Path("pwned-by-pickle").exists()
    arrays = {"vertices": np.zeros((3, 3)), "triangles": np.arange(3), "n": np.float64(2.0)}
    write_pickle(path, arrays)  # numpy arrays and scalars are allowed
    loaded = load_pickle(path)
    assert loaded["vertices"].shape == (3, 3) and loaded["n"] == 2.0


def test_bad_mesh_dicts_name_the_file(tmp_path: Path) -> None:
    path = tmp_path / "u.pkl.gz"
    cases = [
        ({"vertices": [{"x": 0, "y": 0, "z": 0}] * 3, "triangles": [0, 1, 3]}, "out of range"),
        ({"vertices": [{"x": 0, "y": "a", "z": 0}] * 3, "triangles": [0, 1, 2]}, r"vertices\[0\]"),
        ({"vertices": [[0, 0, 0]] * 3, "triangles": [0, 1]}, "multiple of 3"),
        ({"triangles": [0, 1, 2]}, "missing 'vertices'"),
        ([1, 2, 3], "expected a mesh dict"),
    ]
    for data, message in cases:
        write_pickle(path, data)
        with pytest.raises(FormatError, match=message) as err:
            read_mesh(path)
        assert str(path) in str(err.value)


def test_other_mesh_formats(tmp_path: Path, shared: Path) -> None:
    """msgpack and JSON dicts; an OBJ in the dict frame; the original glTF canonicalised."""
    mesh = asset_mesh(shared, SPECS[BOX_UID][0], "+x")
    data = mesh_dict(mesh, BOX_UID)
    folder = tmp_path / BOX_UID
    folder.mkdir()
    (folder / f"{BOX_UID}.json").write_text(json.dumps(data))
    assert read_mesh(folder / f"{BOX_UID}.json").colliders
    msgpack = pytest.importorskip("msgpack")
    packed = folder / f"{BOX_UID}.msgpack.gz"
    packed.write_bytes(gzip.compress(msgpack.packb(data)))
    read = read_mesh(packed)
    assert read.format == "msgpack" and len(read.parts[0].faces) == len(mesh.faces)
    # the original glTF, with objathor's canonical scale (height 0.5 m) and pose
    glb_dir = tmp_path / "glb" / "assets" / BOX_UID
    glb_dir.mkdir(parents=True)
    shutil.copy(shared / SPECS[BOX_UID][0], glb_dir / f"{BOX_UID}.glb")
    annotation = {BOX_UID: {"category": "box", "scale": 0.5, "z_axis_scale": True,
                            "pose_z_rot_angle": 0.0}}  # fmt: skip
    (tmp_path / "glb" / "annotations.json").write_text(json.dumps(annotation))
    result = import_objathor(
        tmp_path / "glb", library=tmp_path / "lib", run=ImportRun(preset="fast", thumbnails=False)
    )
    assert result.summary.outcomes[0].ok, result.summary.outcomes[0].error
    size = AssetLibrary.open(tmp_path / "lib").get(BOX_UID).meta.size
    gx, gz, gy = mesh.size  # asset_mesh(front +x) maps glTF (x, y, z) to (x, -z, y)
    s = 0.5 / gy
    # Blender -Y (= glTF +z) is the front, +X
    assert size == pytest.approx((gz * s, gx * s, 0.5), abs=1e-5)


def test_directory_layouts(tmp_path: Path, shared: Path) -> None:
    """DIR may be the assets folder; per-asset annotations stand in for the global file."""
    build_objathor_dir(tmp_path / "dir", shared, (CLOCK_UID,))
    global_file = tmp_path / "dir" / "annotations.json.gz"
    entry = read_annotation_file(global_file)[CLOCK_UID]
    global_file.unlink()
    with gzip.open(tmp_path / "dir" / "assets" / CLOCK_UID / "annotations.json.gz", "wt") as f:
        json.dump(entry, f)
    (job,) = plan_objathor(tmp_path / "dir" / "assets")
    assert job.uid == CLOCK_UID and job.annotation["category"] == "wall clock"
    assert job.annotation_source.endswith(f"{CLOCK_UID}/annotations.json.gz")


def test_plan_errors(tmp_path: Path, shared: Path) -> None:
    with pytest.raises(InputError, match="not a folder"):
        plan_objathor(tmp_path / "nope")
    (tmp_path / "empty").mkdir()
    with pytest.raises(InputError, match="no objathor assets"):
        plan_objathor(tmp_path / "empty")
    build_objathor_dir(tmp_path / "dir", shared, (BOX_UID,))
    with pytest.raises(InputError, match="did you mean") as err:
        plan_objathor(tmp_path / "dir", [BOX_UID[:-1] + "7"])
    assert BOX_UID in str(err.value)
    (tmp_path / "dir" / "annotations.json.gz").write_bytes(b"\x1f\x8b\x08garbage")
    with pytest.raises(FormatError, match=r"annotations\.json\.gz"):
        plan_objathor(tmp_path / "dir")
    assert parse_uids(["a, b", "c"]) == ["a", "b", "c"]
    assert parse_uids(None) is None


def test_annotation_fields() -> None:
    parsed = parse_annotation(
        {
            "category": "  Eames   chair ",
            "height": "90",
            "mass": -3,
            "onFloor": "true",
            "onWall": 0,
            "receptacle": "maybe",
            "annotations": {"description": "nested"},
            "assetMetadata": {"boundingBox": {"x": 0.6, "y": 0.9, "z": 0.5}},
        },
        "ann.json: u",
    )
    assert parsed.category == "Eames chair" and parsed.height_m == pytest.approx(0.9)
    assert parsed.mass_kg is None and parsed.receptacle is None
    assert parsed.placement == ("floor",) and parsed.description == "nested"
    assert parsed.bbox_unity_m == (0.6, 0.9, 0.5)
    assert any("mass ignored" in w for w in parsed.warnings)
    assert any("receptacle ignored" in w for w in parsed.warnings)
    with pytest.raises(FormatError, match=r"ann\.json"):
        parse_annotation(["not", "a", "dict"], "ann.json")


_json = st.recursive(
    st.none()
    | st.booleans()
    | st.integers()
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=20),
    lambda children: (
        st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4)
    ),
    max_leaves=12,
)
_keys = st.sampled_from(
    [
        "uid", "category", "synset", "description", "description_auto", "height", "width",
        "depth", "mass", "receptacle", "onFloor", "onWall", "onObject", "onCeiling", "scale",
        "z_axis_scale", "pose_z_rot_angle", "license_info", "thor_metadata", "assetMetadata",
        "annotations",
    ]
)  # fmt: skip


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.one_of(_json, st.dictionaries(_keys, _json, max_size=10)))
def test_annotation_reader_never_crashes(raw) -> None:
    """Any JSON value: a checked annotation, or a FormatError for a non-object; never more."""
    try:
        parsed = parse_annotation(raw, "fuzz")
    except FormatError:
        assert not isinstance(raw, dict)
        return
    assert isinstance(raw, dict)
    for value in (parsed.height_m, parsed.mass_kg, parsed.scale_m, parsed.width_m):
        assert value is None or (np.isfinite(value) and value > 0)
    assert np.isfinite(parsed.pose_z_rot_rad)
    assert parsed.placement is None or (
        parsed.placement and set(parsed.placement) <= set(PLACEMENTS)
    )
    assert parsed.bbox_unity_m is None or min(parsed.bbox_unity_m) > 0
    json.dumps(parsed.as_report())  # JSON-able for derivation.json


def test_options_are_picklable() -> None:
    """Jobs and options travel to worker processes."""
    options = ObjathorOptions(colliders="coacd")
    assert pickle.loads(pickle.dumps(options)) == options
