"""scripts/check_imports.py on small module trees made for each test: it sees imports inside
functions and under TYPE_CHECKING, forbidden and unused edges, and a doc table that drifts."""

from __future__ import annotations

import importlib.util
import sys
import textwrap
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _load_checker() -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "check_imports_under_test", ROOT / "scripts" / "check_imports.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up while the class is made
    spec.loader.exec_module(module)
    return module


ci = _load_checker()

# a small project: app.low (bottom), app.mid (may import low), app.top (may import mid and low)
MAP = ci.PackageMap(
    allowed={
        "app": ("the package root", ()),
        "app.base": ("the errors", ()),
        "app.low": ("the bottom layer", ()),
        "app.mid": ("the middle layer", ("app.low",)),
        "app.top": ("the top layer", ("app.mid", "app.low")),
    },
    foundation=("app.base",),
)
BASE_TREE = {
    "app/__init__.py": "",
    "app/base.py": "class AppError(Exception): ...\n",
    "app/low/__init__.py": "",
    "app/low/shapes.py": "from app.base import AppError\n",
    "app/mid/__init__.py": "",
    "app/mid/rooms.py": "from app.low.shapes import AppError\n",
    "app/top/__init__.py": "",
    "app/top/job.py": "from app.mid import rooms\nfrom app.low import shapes\n",
}


def write_tree(root: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text), encoding="utf-8")
    return root


def problems(root: Path, pmap: object = MAP) -> list[str]:
    edges, known = ci.import_edges(root, ("app",))
    return (
        ci.check_edges(edges, known, pmap, root)
        + ci.unused_allowed(edges, pmap)
        + ci.check_cycles(edges, pmap)
    )


def test_a_clean_tree_has_no_problem(tmp_path: Path) -> None:
    assert problems(write_tree(tmp_path, BASE_TREE)) == []


def test_a_cycle_through_an_import_inside_a_function_is_found(tmp_path: Path) -> None:
    tree = {
        **BASE_TREE,
        "app/low/solve.py": "from app.low.pockets import open_pockets\n",
        "app/low/pockets.py": """\
            def open_pockets():
                from app.low.solve import hard_checks
                return hard_checks
            """,
    }
    found = problems(write_tree(tmp_path, tree))
    assert len(found) == 1
    first, members, *edges = found[0].splitlines()
    assert first == (
        "module import cycle through 2 modules: app.low.pockets -> app.low.solve -> app.low.pockets"
    )
    assert members == "  modules: app.low.pockets, app.low.solve"
    assert "  app/low/pockets.py:2: app.low.pockets -> app.low.solve (function level)" in edges
    assert "  app/low/solve.py:1: app.low.solve -> app.low.pockets (module level)" in edges


def test_a_cycle_through_a_type_checking_import_is_found(tmp_path: Path) -> None:
    tree = {
        **BASE_TREE,
        "app/mid/plan.py": "from app.mid.walls import Wall\n",
        "app/mid/walls.py": """\
            from typing import TYPE_CHECKING

            if TYPE_CHECKING:
                from app.mid.plan import Plan
            else:
                import app.low.shapes
            """,
    }
    found = problems(write_tree(tmp_path, tree))
    assert len(found) == 1 and found[0].startswith("module import cycle through 2 modules")
    assert "  app/mid/walls.py:4: app.mid.walls -> app.mid.plan (type level)" in found[0]


def test_cycles_between_packages_are_found_and_every_cycle_is_printed(tmp_path: Path) -> None:
    tree = {
        **BASE_TREE,
        # low -> mid (lazily, and not allowed): a package cycle low -> mid -> low
        "app/low/lookup.py": "def find():\n    from app.mid.rooms import AppError\n",
        # and a second, separate module cycle inside top
        "app/top/a.py": "import app.top.b\n",
        "app/top/b.py": "def f():\n    import app.top.a\n",
    }
    found = problems(write_tree(tmp_path, tree))
    assert "app/low/lookup.py:2: app.low may not import app.mid (app.mid.rooms)" in found
    cycles = [p.splitlines()[0] for p in found if "cycle" in p]
    assert cycles == [
        "module import cycle through 2 modules: app.top.a -> app.top.b -> app.top.a",
        "package import cycle through 2 packages: app.low -> app.mid -> app.low",
    ]


def test_a_forbidden_edge_is_named_with_its_file_and_line(tmp_path: Path) -> None:
    tree = {**BASE_TREE, "app/low/upward.py": "import os\n\nfrom app.top import job\n"}
    found = problems(write_tree(tmp_path, tree))
    assert found[0] == "app/low/upward.py:3: app.low may not import app.top (app.top.job)"


def test_relative_imports_resolve_to_the_module_they_name(tmp_path: Path) -> None:
    tree = {**BASE_TREE, "app/low/upward.py": "from ..top.job import run\n"}
    found = problems(write_tree(tmp_path, tree))
    assert found[0] == "app/low/upward.py:1: app.low may not import app.top (app.top.job)"


def test_an_allowed_edge_nothing_uses_fails(tmp_path: Path) -> None:
    tree = {**BASE_TREE, "app/top/job.py": "from app.mid import rooms\n"}
    found = problems(write_tree(tmp_path, tree))
    assert found == [
        "package map: app.top may import app.low, but none of its modules does (drop it)"
    ]


def test_reading_a_package_s_data_files_counts_as_using_it(tmp_path: Path) -> None:
    tree = {
        **BASE_TREE,
        "app/top/job.py": """\
            from importlib import resources

            from app.mid import rooms

            def table():
                return resources.files("app.low").joinpath("table.json").read_text()
            """,
    }
    assert problems(write_tree(tmp_path, tree)) == []


def test_modules_outside_the_map_and_empty_entries_fail_unless_planned(tmp_path: Path) -> None:
    tree = {**BASE_TREE, "app/extra/__init__.py": ""}
    allowed = {**MAP.allowed, "app.compose": ("planned", ("app.mid",))}
    pmap = ci.PackageMap(allowed=allowed, foundation=MAP.foundation)
    found = problems(write_tree(tmp_path, tree), pmap)
    assert "package map: app.compose has no module (mark it planned or drop it)" in found
    assert not any("app.extra" in line for line in found)  # it belongs to the root, "app"
    planned = ci.PackageMap(allowed=allowed, foundation=MAP.foundation, planned=("app.compose",))
    assert problems(tmp_path, planned) == []
    write_tree(tmp_path, {"app/compose/__init__.py": "from app.mid import rooms\n"})
    assert problems(tmp_path, planned) == [
        "package map: app.compose has modules now: drop it from PLANNED"
    ]


def test_a_lazy_only_package_imported_at_module_level_fails(tmp_path: Path) -> None:
    tree = {
        **BASE_TREE,
        "app/top/job.py": """\
            from app.low import shapes

            def run():
                from app.mid import rooms
            """,
    }
    pmap = ci.PackageMap(
        MAP.allowed, foundation=MAP.foundation, lazy_only=(("app.top", "app.low"),)
    )
    found = problems(write_tree(tmp_path, tree), pmap)
    assert found == ["app/top/job.py:1: app.low.shapes imported outside a function"]


def test_groups_map_modules_of_a_flat_package(tmp_path: Path) -> None:
    allowed = {
        **MAP.allowed,
        "app.low:mesh": ("meshes", ()),
        "app.low": ("rest", ("app.low:mesh",)),
    }
    pmap = ci.PackageMap(allowed, {"app.low:mesh": ("app.low.mesh_load",)}, MAP.foundation)
    tree = {
        **BASE_TREE,
        "app/low/mesh_load.py": "from app.low.shapes import AppError\n",
        "app/low/shapes.py": "def f():\n    from app.low.mesh_load import x\n",
    }
    found = problems(write_tree(tmp_path, tree), pmap)
    assert pmap.package_of("app.low.mesh_load") == "app.low:mesh"
    assert "app/low/mesh_load.py:1: app.low:mesh may not import app.low (app.low.shapes)" in found


def test_the_doc_table_must_match_the_map() -> None:
    rows = ci.table_rows(MAP)
    table = "## Package map\n\n| package | owns | may import |\n|---|---|---|\n" + "\n".join(rows)
    assert ci.check_doc(table, MAP, "doc.md") == []
    drifted = table.replace("| `app.mid`, `app.low` |", "| `app.mid` |").replace(
        "| `app.low` | the bottom layer", "| `app.bottom` | the bottom layer"
    )
    assert ci.check_doc(drifted, MAP, "doc.md") == [
        "doc.md: package app.low of the import map is not in the table",
        "doc.md: package app.bottom of the table is not in the import map",
        "doc.md: app.top may import differs from the import map "
        "(only in the doc: -; only in the map: app.low)",
    ]
    assert ci.check_doc("no table here", MAP, "doc.md")[0].startswith("doc.md: no package table")
    # a table in another section is not the package table
    elsewhere = table.replace("## Package map", "## Data flow")
    assert ci.check_doc(elsewhere, MAP, "doc.md")[0].startswith("doc.md: no package table")


def test_the_project_map_is_consistent() -> None:
    """Every package the project map names exists in the map; no foundation package is named."""
    for package, (_, may) in ci.ALLOWED.items():
        for target in may:
            assert target in ci.ALLOWED, (package, target)
            assert target not in ci.FOUNDATION, (package, target)


@pytest.mark.parametrize("cycle_size", [1, 3])
def test_cycles_finds_self_loops_and_longer_rings(cycle_size: int) -> None:
    ring = [f"m{i}" for i in range(cycle_size)]
    graph = {node: {ring[(i + 1) % cycle_size]} for i, node in enumerate(ring)}
    graph["tail"] = {"m0"}
    assert ci.cycles(graph) == [ring]
    assert ci.shortest_cycle(graph, "m0") == [*ring, "m0"]
    assert ci.cycles({"a": {"b"}, "b": set()}) == []
