"""Check the import graph of holomj and asset_pipeline: no cycle, no import a package may not make.

Every package of ``holomj`` may import only the packages its line of ``ALLOWED`` names (and
itself); imports inside functions count too (a lazy import is still a dependency), imports under
``if TYPE_CHECKING:`` as well. ``asset_pipeline`` may be imported by holomj only from the
packages of ``MAY_IMPORT_ASSET_PIPELINE``, and there only inside functions. Modules must not form
a cycle through module-level imports, and packages must not form a cycle at all.

    python scripts/check_imports.py          # exit 1 and one line per problem when any is found
    python scripts/check_imports.py --map    # print the package map

CI runs it (scripts/test.sh).
"""

from __future__ import annotations

import argparse
import ast
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TOP_LEVEL = ("holomj", "asset_pipeline")

# package -> (what it owns, the packages it may import)
ALLOWED: dict[str, tuple[str, tuple[str, ...]]] = {
    "holomj.errors": ("the HolomjError types", ()),
    "holomj.version": ("the version string", ()),
    "holomj.file_names": ("the file and folder names of output folders and libraries", ()),
    "holomj.atomic": ("the one atomic file writer and the one folder writer", ()),
    "holomj.seeds": ("seed -> per-stage generators", ()),
    "holomj.data": ("knowledge and catalogue data files", ()),
    "holomj.spec": ("pure data: scene, plan, assets, report, robot record", ("holomj.errors",)),
    "holomj.library": (
        "asset libraries on disk (read-only views), their location",
        ("holomj.errors", "holomj.spec", "holomj.atomic"),
    ),
    "holomj.layout": (
        "pure geometry: floor plans, doors/windows, furniture solver, wall objects",
        ("holomj.errors", "holomj.seeds", "holomj.spec", "holomj.library", "holomj.data"),
    ),
    "holomj.retrieval": (
        "asset and material scoring (text, visual, size), embedding cache",
        ("holomj.errors", "holomj.atomic", "holomj.spec", "holomj.library", "holomj.data"),
    ),
    "holomj.plan": (
        "request -> ScenePlan: offline knowledge-base planner, LLM planner",
        (
            "holomj.errors",
            "holomj.seeds",
            "holomj.spec",
            "holomj.library",
            "holomj.layout",
            "holomj.retrieval",
            "holomj.data",
        ),
    ),
    "holomj.compose": (
        "plan + assets -> SceneSpec: house shell, room furnishing, small-object choices, "
        "the relation report",
        (
            "holomj.errors",
            "holomj.seeds",
            "holomj.spec",
            "holomj.library",
            "holomj.layout",
            "holomj.data",
        ),
    ),
    "holomj.importers": (
        "ProcTHOR/Holodeck house JSON and SceneDef -> SceneSpec",
        ("holomj.errors", "holomj.spec", "holomj.library", "holomj.data"),
    ),
    "holomj.mjcf": (
        "SceneSpec -> MjSpec -> compiled model (the only MJCF builder)",
        ("holomj.errors", "holomj.spec", "holomj.library"),
    ),
    "holomj.physics": (
        "penetration audit, settle, stability, repair, spawn-and-drop (in memory)",
        (
            "holomj.errors",
            "holomj.seeds",
            "holomj.spec",
            "holomj.library",
            "holomj.mjcf",
        ),
    ),
    "holomj.robots": (
        "robot registry, preparation, floor spot, attaching (in memory)",
        (
            "holomj.errors",
            "holomj.seeds",
            "holomj.spec",
            "holomj.library",
            "holomj.mjcf",
            "holomj.physics",
        ),
    ),
    "holomj.rendering": (
        "headless rendering, plan view, HTML report (in memory)",
        ("holomj.errors", "holomj.spec", "holomj.library", "holomj.mjcf", "holomj.physics"),
    ),
    "holomj.evaluation": (
        "scene metrics from a folder's geometry (never the planner): fidelity, support, reach",
        ("holomj.errors", "holomj.spec", "holomj.data"),
    ),
    "holomj.formats": (
        "output formats in memory: objects.json, navigation map, summaries, GLB, USD, URDF",
        (
            "holomj.errors",
            "holomj.spec",
            "holomj.library",
            "holomj.mjcf",
            "holomj.physics",
        ),
    ),
    "holomj.edit": (
        "scene edit operations applied in memory (add, move, remove, replace, ...)",
        (
            "holomj.errors",
            "holomj.seeds",
            "holomj.spec",
            "holomj.library",
            "holomj.layout",
            "holomj.retrieval",
            "holomj.plan",
            "holomj.mjcf",
            "holomj.physics",
        ),
    ),
    "holomj.refinement": (
        "refine decisions in memory: instructions, goals, offline and LLM planners, safety, "
        "pointing",
        ("holomj.errors", "holomj.spec", "holomj.plan", "holomj.evaluation"),
    ),
    "holomj.jobs": (
        "one module per user-facing job; the output folder (file names, atomic I/O)",
        (
            "holomj.edit",
            "holomj.refinement",
            "holomj.errors",
            "holomj.atomic",
            "holomj.seeds",
            "holomj.data",
            "holomj.spec",
            "holomj.library",
            "holomj.layout",
            "holomj.compose",
            "holomj.retrieval",
            "holomj.plan",
            "holomj.importers",
            "holomj.mjcf",
            "holomj.physics",
            "holomj.robots",
            "holomj.rendering",
            "holomj.formats",
            "holomj.evaluation",
            "asset_pipeline",
        ),
    ),
    "holomj.batch": (
        "many jobs on a local worker pool or Ray, resumable",
        ("holomj.errors", "holomj.atomic", "holomj.spec", "holomj.jobs"),
    ),
    "holomj.api": (
        "the Python API re-exported from holomj",
        ("holomj.errors", "holomj.spec", "holomj.library", "holomj.jobs", "holomj.seeds"),
    ),
    "holomj.cli": (
        "thin typer commands: parse options, call one job, print",
        (
            "holomj.api",
            "holomj.errors",
            "holomj.seeds",
            "holomj.spec",
            "holomj.library",
            "holomj.jobs",
            "holomj.batch",
            "holomj.importers",  # the list of input formats, for --format
        ),
    ),
    "holomj.__main__": ("python -m holomj", ("holomj.cli",)),
    "holomj": ("the package root: version and the lazy API", ("holomj.api",)),
    "asset_pipeline": (
        "offline asset processing: meshes, CoACD, surfaces, thumbnails, library writer",
        (
            "holomj",
            "holomj.errors",
            "holomj.atomic",
            "holomj.seeds",
            "holomj.spec",
            "holomj.library",
            "holomj.mjcf",
            "holomj.rendering",
        ),
    ),
}
MAY_IMPORT_ASSET_PIPELINE = ("holomj.jobs",)
# imported by anyone: they import nothing of ours
FOUNDATION = ("holomj.errors", "holomj.version", "holomj.file_names")


def modules() -> dict[str, Path]:
    """Every module of the checked packages: dotted name -> file."""
    found = {}
    for top in TOP_LEVEL:
        for path in sorted((ROOT / top).rglob("*.py")):
            parts = path.relative_to(ROOT).with_suffix("").parts
            name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
            found[name] = path
    return found


def package_of(module: str) -> str:
    """The package of ``ALLOWED`` a module belongs to (the longest matching prefix)."""
    best = ""
    for package in ALLOWED:
        if (module == package or module.startswith(package + ".")) and len(package) > len(best):
            best = package
    return best or module


class Import:
    """One import statement's target module, and whether it sits inside a function."""

    def __init__(self, target: str, line: int, lazy: bool) -> None:
        self.target, self.line, self.lazy = target, line, lazy


def imports_of(name: str, path: Path, known: dict[str, Path]) -> list[Import]:
    """The imports of our own modules that ``name`` makes."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found: list[Import] = []

    def resolve(dotted: str) -> str | None:
        while dotted and dotted not in known:
            dotted = dotted.rpartition(".")[0]
        return dotted or None

    def visit(node: ast.AST, lazy: bool) -> None:
        for child in ast.iter_child_nodes(node):
            inner = lazy or isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef)
            if isinstance(child, ast.Import):
                for alias in child.names:
                    target = resolve(alias.name)
                    if target:
                        found.append(Import(target, child.lineno, lazy))
            elif isinstance(child, ast.ImportFrom):
                base = child.module or ""
                if child.level:
                    parts = package.split(".")[: len(package.split(".")) - child.level + 1]
                    base = ".".join([*parts, base] if base else parts)
                for alias in child.names:
                    target = resolve(f"{base}.{alias.name}") or resolve(base)
                    if target:
                        found.append(Import(target, child.lineno, lazy))
            visit(child, inner)

    visit(tree, False)
    return [i for i in found if i.target != name]


def find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """One cycle of ``graph`` as a list of nodes (first == last), or None."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def dfs(node: str) -> list[str] | None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return [*stack[stack.index(nxt) :], nxt]
            if nxt not in state and (cycle := dfs(nxt)):
                return cycle
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state and (cycle := dfs(node)):
            return cycle
    return None


def check() -> list[str]:
    """Every problem of the import graph, one line each."""
    known = modules()
    problems = []
    module_graph: dict[str, set[str]] = defaultdict(set)
    package_graph: dict[str, set[str]] = defaultdict(set)
    for name, path in known.items():
        source = package_of(name)
        if source not in ALLOWED:
            problems.append(f"{path.relative_to(ROOT)}: package {source} is not in the map")
            continue
        allowed = set(ALLOWED[source][1]) | set(FOUNDATION)
        for imp in imports_of(name, path, known):
            target = package_of(imp.target)
            where = f"{path.relative_to(ROOT)}:{imp.line}"
            if not imp.lazy:
                module_graph[name].add(imp.target)
            if target == source:
                continue
            if target == "asset_pipeline" and source.startswith("holomj"):
                if source not in MAY_IMPORT_ASSET_PIPELINE:
                    problems.append(f"{where}: {source} imports asset_pipeline")
                elif not imp.lazy:
                    problems.append(f"{where}: asset_pipeline imported at module level")
                continue
            if target not in allowed:
                problems.append(f"{where}: {source} may not import {target} ({imp.target})")
            package_graph[source].add(target)
    if cycle := find_cycle(module_graph):
        problems.append("module import cycle: " + " -> ".join(cycle))
    if cycle := find_cycle(package_graph):
        problems.append("package import cycle: " + " -> ".join(cycle))
    return problems


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", action="store_true", help="print the package map")
    args = parser.parse_args()
    if args.map:
        for package, (owns, may) in ALLOWED.items():
            print(f"{package}: {owns}; may import: {', '.join(may) or 'nothing of ours'}")
        return 0
    problems = check()
    for line in dict.fromkeys(problems):  # one line per problem, in order
        print(line)
    print(f"import graph: {len(modules())} modules, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
