"""Synthesis on demand into a library: content-addressed, reused, atomic, safe in parallel."""

from __future__ import annotations

import multiprocessing
import os
from pathlib import Path

import pytest

from asset_pipeline.library_writer import write_library
from holomj.jobs.synthesis import (
    PROXY_SOURCE,
    SYNTHESISED_SOURCE,
    LibrarySynthesiser,
    fit_size,
    generator_for,
    synthesise,
    synthesise_proxy,
)
from holomj.library.store import AssetLibrary


@pytest.fixture
def library_root(tmp_path: Path) -> Path:
    return write_library(tmp_path / "lib", "test", [])


def test_synthesis_is_content_addressed_and_reused(library_root: Path) -> None:
    first = synthesise(library_root, "sofa", (0.9, 2.0, 0.85), 1, {"colour": "pink"})
    assert not first.reused and first.how == "synthesised"
    assert first.asset_id.startswith("sofa_") and len(first.asset_id) == len("sofa_") + 12
    meta_file = library_root / first.folder / "asset.json"
    stamp = meta_file.stat().st_mtime_ns
    again = synthesise(library_root, "Sofa", (0.9, 2.0, 0.85), 1, {"colour": "pink"})
    assert again.asset_id == first.asset_id and again.reused
    assert meta_file.stat().st_mtime_ns == stamp  # nothing rewritten
    other = synthesise(library_root, "sofa", (0.9, 2.0, 0.85), 1, {"colour": "blue"})
    assert other.asset_id != first.asset_id
    library = AssetLibrary.open(library_root)
    meta = library.get(first.asset_id).meta
    assert meta.source == SYNTHESISED_SOURCE and meta.attributes == {"colour": "pink"}
    assert first.attributes_honoured == {"colour": "pink"}
    assert "pink" in meta.description


def test_size_is_clamped_and_reported(library_root: Path) -> None:
    size, notes = fit_size("sofa", (0.9, 5.0, 0.85))
    assert size == (0.9, 3.2, 0.85) and "clamped" in notes[0]
    made = synthesise(library_root, "sofa", (0.9, 5.0, 0.85), 0)
    assert made.size == (0.9, 3.2, 0.85) and any("clamped" in n for n in made.notes)
    assert fit_size("sofa", (0.9, 2.0, 0.85)) == ((0.9, 2.0, 0.85), [])


def test_articulated_categories_are_synthesised_articulated(
    library_root: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from asset_pipeline import default_library

    wanted = {"colour": "white", "handles.material": "brass"}
    made = synthesise(library_root, "kitchen counter", (0.62, 1.8, 0.9), 2, wanted)
    meta = AssetLibrary.open(library_root).get(made.asset_id).meta
    assert meta.articulated and meta.category == "kitchen_counter"
    assert made.attributes_honoured == wanted and meta.size == (0.62, 1.8, 0.9)
    assert made.parts_how["handles"].startswith("brass on the handles")
    laptop = synthesise(library_root, "laptop", None, 0, {"colour": "black"})
    assert not AssetLibrary.open(library_root).get(laptop.asset_id).meta.articulated
    # with the switch off the same request makes a rigid asset, under another id
    monkeypatch.setattr(default_library, "ARTICULATED_BY_DEFAULT", False)
    rigid = synthesise(library_root, "kitchen counter", (0.62, 1.8, 0.9), 2, wanted)
    assert rigid.asset_id != made.asset_id
    assert not AssetLibrary.open(library_root).get(rigid.asset_id).meta.articulated


def test_generator_lookup() -> None:
    assert generator_for("Dining Table") == "dining_table"
    assert generator_for("spaceship_console") is None
    assert generator_for(None) is None


def test_proxy_into_the_library(library_root: Path) -> None:
    made = synthesise_proxy(library_root, "Spaceship Console", (0.8, 1.2, 1.1), "floor")
    assert made.how == "proxy" and made.category == "spaceship_console"
    meta = AssetLibrary.open(library_root).get(made.asset_id).meta
    assert meta.proxy and meta.source == PROXY_SOURCE and meta.category == "spaceship_console"
    assert meta.size == (0.8, 1.2, 1.1)
    assert synthesise_proxy(library_root, "spaceship_console", (0.8, 1.2, 1.1)).reused


def _worker(root: str, queue) -> None:
    made = synthesise(Path(root), "armchair", (0.85, 0.85, 0.9), 2, {"colour": "teal"})
    queue.put(made.asset_id)


def test_parallel_synthesis_leaves_one_valid_asset(library_root: Path) -> None:
    context = multiprocessing.get_context("spawn")
    queue = context.Queue()
    workers = [context.Process(target=_worker, args=(str(library_root), queue)) for _ in range(2)]
    for w in workers:
        w.start()
    for w in workers:
        w.join(120)
        assert w.exitcode == 0
    ids = {queue.get(timeout=5), queue.get(timeout=5)}
    assert len(ids) == 1
    library = AssetLibrary.open(library_root)  # loads and checks every file named
    assert [i for i in library.ids() if i != "builtin:box"] == sorted(ids)
    folders = [p for p in library_root.iterdir() if not p.name.startswith(".") and p.is_dir()]
    assert len(folders) == 1


def test_open_library_learns_the_new_asset(library_root: Path) -> None:
    library = AssetLibrary.open(library_root)
    synth = LibrarySynthesiser(library)
    made = synth.synthesise("coffee_table", (0.6, 1.1, 0.42), 0, {"shape": "round"})
    assert made.asset_id in library
    assert library.get(made.asset_id).meta.size[0] == library.get(made.asset_id).meta.size[1]
    proxy = synth.proxy("telescope", (0.5, 0.5, 1.4), "floor", {})
    assert library.get(proxy.asset_id).meta.proxy


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only folders")
def test_read_only_library_goes_to_the_cache(library_root: Path, tmp_path: Path) -> None:
    library = AssetLibrary.open(library_root)
    os.chmod(library_root / "library.json", 0o444)
    os.chmod(library_root, 0o555)
    try:
        synth = LibrarySynthesiser(library, cache_root=tmp_path / "cache")
        made = synth.synthesise("stool", None, 0, {"colour": "red"})
        assert made.library == tmp_path / "cache"
        assert made.asset_id in library and made.asset_id in AssetLibrary.open(tmp_path / "cache")
    finally:
        os.chmod(library_root, 0o755)
        os.chmod(library_root / "library.json", 0o644)
