"""The library writer: validation, atomic replacement, determinism, adding assets."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from asset_pipeline import library_writer
from asset_pipeline.library_writer import (
    AssetBundle,
    add_assets,
    folder_for,
    remove_assets,
    write_library,
)
from holomj.errors import AssetNotFoundError, OutputExistsError, SpecError
from holomj.library.store import AssetLibrary
from holomj.spec.assets import AssetMeta

BOX_OBJ = (
    b"v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\n"
    b"v -0.5 -0.5 1\nv 0.5 -0.5 1\nv 0.5 0.5 1\nv -0.5 0.5 1\n"
    b"f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
    b"f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n"
)


def bundle(asset_id: str, mesh: str = "box.obj", **files: bytes) -> AssetBundle:
    meta = AssetMeta(
        id=asset_id,
        category="box",
        description=f"a test box {asset_id}",
        size=(1.0, 1.0, 1.0),
        mass_kg=10.0,
        visual=[{"mesh": mesh}],
        collision=[{"kind": "box", "size": (0.5, 0.5, 0.5), "pos": (0, 0, 0.5), "volume_m3": 1.0}],
    )
    return AssetBundle(meta=meta, files={mesh: BOX_OBJ, **files})


def snapshot(root: Path) -> dict[str, bytes]:
    return {
        p.relative_to(root).as_posix(): p.read_bytes()
        for p in root.rglob("*")
        if p.is_file() and p.name != ".lock"
    }


def test_written_library_opens(tmp_path: Path) -> None:
    root = write_library(tmp_path / "lib", "test", [bundle("b"), bundle("a:1")])
    lib = AssetLibrary.open(root)
    assert {"a:1", "b"} <= set(lib.ids())
    assert lib.get("a:1").root.name == "a_1"
    index = json.loads((root / "library.json").read_text())
    assert index == {"assets": {"a:1": "a_1", "b": "b"}, "name": "test", "schema_version": "1.0"}


def test_output_is_byte_deterministic(tmp_path: Path) -> None:
    first = snapshot(write_library(tmp_path / "one", "t", [bundle("a"), bundle("b")]))
    second = snapshot(write_library(tmp_path / "two", "t", [bundle("a"), bundle("b")]))
    assert first == second
    text = first["a/asset.json"].decode()
    assert (
        text.endswith("}\n")
        and text == json.dumps(json.loads(text), indent=2, sort_keys=True) + "\n"
    )


def test_existing_library_needs_overwrite(tmp_path: Path) -> None:
    root = write_library(tmp_path / "lib", "t", [bundle("a")])
    before = snapshot(root)
    with pytest.raises(OutputExistsError):
        write_library(root, "t", [bundle("b")])
    assert snapshot(root) == before
    write_library(root, "t", [bundle("b")], overwrite=True)
    assert sorted(AssetLibrary.open(root).ids()) == ["b", "builtin:box"]


def test_duplicate_ids_are_rejected(tmp_path: Path) -> None:
    with pytest.raises(SpecError, match="duplicate asset id"):
        write_library(tmp_path / "lib", "t", [bundle("a"), bundle("a")])
    assert not (tmp_path / "lib").exists()


def test_folder_clash_is_rejected(tmp_path: Path) -> None:
    with pytest.raises(SpecError, match="already used"):
        write_library(tmp_path / "lib", "t", [bundle("a:b"), bundle("a|b")])


@pytest.mark.parametrize(
    "path", ["../evil.obj", "/abs.obj", "a/../../x.obj", "a\\b.obj", "./a.obj"]
)
def test_unsafe_paths_are_rejected(tmp_path: Path, path: str) -> None:
    good = bundle("a")
    bad = AssetBundle(meta=good.meta, files={**good.files, path: b"x"})
    with pytest.raises(SpecError, match="unsafe file path"):
        write_library(tmp_path / "lib", "t", [bad])
    assert list(tmp_path.iterdir()) == []


def test_missing_file_is_rejected(tmp_path: Path) -> None:
    with pytest.raises(SpecError, match="missing"):
        write_library(tmp_path / "lib", "t", [AssetBundle(meta=bundle("a").meta, files={})])


def test_invalid_meta_is_rejected_and_leaves_old_library(tmp_path: Path) -> None:
    root = write_library(tmp_path / "lib", "t", [bundle("a")])
    before = snapshot(root)
    broken = AssetMeta.model_construct(**{**bundle("b").meta.__dict__, "size": (1.0, -1.0, 1.0)})
    with pytest.raises(SpecError):
        write_library(
            root,
            "t",
            [bundle("c"), AssetBundle(meta=broken, files={"box.obj": BOX_OBJ})],
            overwrite=True,
        )
    assert snapshot(root) == before
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.endswith(".lock")) == ["lib"]


def test_failure_midway_leaves_old_library(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    root = write_library(tmp_path / "lib", "t", [bundle("a")])
    before = snapshot(root)
    real = library_writer._fill_bundle
    calls = []

    def flaky(folder: Path, item: AssetBundle, store: Path) -> None:
        calls.append(item.meta.id)
        if len(calls) % 2 == 0:  # the second asset of every write
            raise OSError("disk full")
        real(folder, item, store)

    monkeypatch.setattr(library_writer, "_fill_bundle", flaky)
    with pytest.raises(OSError, match="disk full"):
        write_library(root, "t", [bundle("b"), bundle("c")], overwrite=True)
    with pytest.raises(OSError, match="disk full"):
        add_assets(root, [bundle("d"), bundle("e")])
    assert snapshot(root) == before
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.endswith(".lock")) == ["lib"]


def test_add_assets_adds_and_replaces(tmp_path: Path) -> None:
    root = write_library(tmp_path / "lib", "t", [bundle("a"), bundle("b", extra=b"old")])
    add_assets(root, [bundle("c"), bundle("b", mesh="new.obj")])
    lib = AssetLibrary.open(root)
    assert sorted(lib.ids()) == ["a", "b", "builtin:box", "c"]
    assert [v.mesh for v in lib.get("b").meta.visual] == ["new.obj"]
    assert not (root / "b" / "extra").exists() and not (root / "b" / "box.obj").exists()
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.endswith(".lock")) == ["lib"]
    with pytest.raises(SpecError, match="duplicate"):
        add_assets(root, [bundle("x"), bundle("x")])


def test_add_assets_needs_a_library(tmp_path: Path) -> None:
    with pytest.raises(SpecError, match="not an asset library"):
        add_assets(tmp_path, [bundle("a")])


def test_folder_for_makes_plain_names() -> None:
    assert folder_for("holo:chair|v2+x") == "holo_chair_v2_x"
    assert folder_for(".hidden") == "_hidden"


def test_remove_assets_and_sweep(tmp_path: Path) -> None:
    root = write_library(tmp_path / "lib", "t", [bundle("a"), bundle("b")])
    (root / "stray").mkdir()  # debris of an interrupted write: not in the index
    assert sorted(remove_assets(root, ["a"])) == ["a", "stray"]
    assert AssetLibrary.open(root).ids() == ["b", "builtin:box"]
    with pytest.raises(AssetNotFoundError, match="'a'"):
        remove_assets(root, ["a"])


def test_replacing_an_asset_writes_a_fresh_folder_before_committing(tmp_path: Path) -> None:
    root = write_library(tmp_path / "lib", "t", [bundle("a")])
    add_assets(root, [bundle("a", mesh="new.obj")])
    lib = AssetLibrary.open(root)
    assert lib.get("a").root.name == "a-2"
    assert not (root / "a").exists()


PNG_A = b"\x89PNG\r\n\x1a\n" + b"texture A" * 50
PNG_B = b"\x89PNG\r\n\x1a\n" + b"texture B" * 50


def textured(asset_id: str, png: bytes) -> AssetBundle:
    base = bundle(asset_id)
    meta = base.meta.model_copy(
        update={"visual": [base.meta.visual[0].model_copy(update={"texture": "tex.png"})]}
    )
    return AssetBundle(meta=meta, files={**base.files, "tex.png": png})


def test_shared_images_are_written_once_and_linked(tmp_path: Path) -> None:
    root = write_library(
        tmp_path / "lib", "t", [textured("a", PNG_A), textured("b", PNG_A), textured("c", PNG_B)]
    )
    a, b, c = (root / name / "tex.png" for name in "abc")
    assert a.read_bytes() == PNG_A and c.read_bytes() == PNG_B
    assert a.stat().st_ino == b.stat().st_ino != c.stat().st_ino
    blobs = sorted((root / library_writer.LIBRARY_BLOBS).iterdir())
    assert len(blobs) == 2 and {p.stat().st_nlink for p in blobs} == {2, 3}
    # The linked files read like any other: the library opens and finds the texture.
    assert AssetLibrary.open(root).get("a").path("tex.png").read_bytes() == PNG_A


def test_added_assets_link_existing_blobs_and_unused_blobs_are_swept(tmp_path: Path) -> None:
    root = write_library(tmp_path / "lib", "t", [textured("a", PNG_A)])
    add_assets(root, [textured("b", PNG_A), textured("c", PNG_B)])
    assert (root / "a" / "tex.png").stat().st_ino == (root / "b" / "tex.png").stat().st_ino
    store = root / library_writer.LIBRARY_BLOBS
    assert len(list(store.iterdir())) == 2
    remove_assets(root, ["c"])  # the only user of PNG_B: its blob goes
    assert [p.read_bytes() for p in store.iterdir()] == [PNG_A]
    remove_assets(root, ["a"])  # b still links PNG_A
    assert (root / "b" / "tex.png").read_bytes() == PNG_A and len(list(store.iterdir())) == 1
    add_assets(root, [textured("b", PNG_B)])  # replacing b's texture frees PNG_A
    assert [p.read_bytes() for p in store.iterdir()] == [PNG_B]


def test_images_are_copied_where_links_fail(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def no_links(source: object, target: object) -> None:
        raise OSError(library_writer.errno.EXDEV, "cross-device link")

    monkeypatch.setattr(library_writer.os, "link", no_links)
    root = write_library(tmp_path / "lib", "t", [textured("a", PNG_A), textured("b", PNG_A)])
    a, b = root / "a" / "tex.png", root / "b" / "tex.png"
    assert a.read_bytes() == b.read_bytes() == PNG_A
    assert a.stat().st_ino != b.stat().st_ino
