"""Check the import graph of holomj and asset_pipeline against the package map.

Every import of our own modules counts: at module level, inside functions (a lazy import is still
a dependency) and under ``if TYPE_CHECKING:``. The checker fails on

- a module outside the map, or a map entry with no module (unless it is marked planned);
- an import a package's line of ``ALLOWED`` does not name (the foundation packages excepted);
- an import of ``asset_pipeline`` from holomj made at module level (holomj stays light);
- any cycle of modules and any cycle of packages (each one printed, with the imports inside it);
- an allowed import nothing in the code makes (the map stays true);
- a package table in ``docs/architecture.md`` that differs from ``ALLOWED``.

    python scripts/check_imports.py          # exit 1 and one entry per problem when any is found
    python scripts/check_imports.py --map    # print the package map (the doc's table rows)

CI runs it (scripts/test.sh).
"""

from __future__ import annotations

import argparse
import ast
import re
import sys
from collections import defaultdict
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TOP_LEVEL = ("holomj", "asset_pipeline")
DOC = Path("docs") / "architecture.md"
TABLE_HEADING = "Package map"  # the doc's section whose table must match ALLOWED

# imported by anyone, import nothing of ours; never named in an ALLOWED line
FOUNDATION = ("holomj.errors", "holomj.version", "holomj.file_names")


def _holomj(names: str) -> tuple[str, ...]:
    """``"spec library"`` -> ``("holomj.spec", "holomj.library")``."""
    return tuple(f"holomj.{name}" for name in names.split())


def _asset_pipeline(names: str) -> tuple[str, ...]:
    """``"load :mesh"`` -> ``("asset_pipeline.load", "asset_pipeline:mesh")`` (a group)."""
    return tuple(f"asset_pipeline{'' if n[0] == ':' else '.'}{n}" for n in names.split())


# package -> (what it owns, the packages it may import besides itself and FOUNDATION)
ALLOWED: dict[str, tuple[str, tuple[str, ...]]] = {
    "holomj.errors": ("the HolomjError types", ()),
    "holomj.version": ("the version string", ()),
    "holomj.file_names": ("the file and folder names of output folders and libraries", ()),
    "holomj.atomic": ("the one atomic file writer and the one folder writer", ()),
    "holomj.seeds": ("seed -> per-stage generators", ()),
    "holomj.data": ("knowledge and catalogue data files", ()),
    "holomj.spec": (
        "pure data: scene, plan, assets, report, robot record, materials",
        _holomj("data"),
    ),
    "holomj.library": (
        "asset libraries on disk (read-only views), their location",
        _holomj("spec data"),
    ),
    "holomj.layout": (
        "pure geometry: floor plans, doors/windows, furniture solver, wall objects",
        _holomj("spec"),
    ),
    "holomj.retrieval": (
        "asset and material scoring (text, visual, size), embedding cache",
        _holomj("atomic spec library data"),
    ),
    "holomj.plan": (
        "request -> ScenePlan: offline knowledge-base planner, LLM planner",
        _holomj("seeds spec library layout retrieval data"),
    ),
    "holomj.compose": (
        "plan + assets -> SceneSpec: house shell, room furnishing, small objects, relation report",
        _holomj("seeds spec library layout retrieval data"),
    ),
    "holomj.importers": (
        "ProcTHOR/Holodeck house JSON and SceneDef -> SceneSpec",
        _holomj("spec library data"),
    ),
    "holomj.mjcf": (
        "SceneSpec -> MjSpec -> compiled model (the only MJCF builder)",
        _holomj("spec library"),
    ),
    "holomj.physics": (
        "penetration audit, settle, stability, repair, spawn-and-drop (in memory)",
        _holomj("spec library mjcf"),
    ),
    "holomj.robots": (
        "robot registry, preparation, floor spot, attaching (in memory)",
        _holomj("spec mjcf physics"),
    ),
    "holomj.rendering": (
        "headless rendering, plan view, HTML report (in memory)",
        _holomj("spec library mjcf"),
    ),
    "holomj.evaluation": (
        "scene metrics from a folder's geometry (never the planner): fidelity, support, reach",
        _holomj("spec data"),
    ),
    "holomj.formats": (
        "output formats in memory: objects.json, navigation map, summaries, GLB, USD, URDF",
        _holomj("spec mjcf physics"),
    ),
    "holomj.edit": (
        "scene edit operations applied in memory (add, move, remove, replace, ...)",
        _holomj("seeds spec library layout retrieval plan mjcf physics"),
    ),
    "holomj.refinement": (
        "refine decisions in memory: instructions, goals, offline and LLM planners, safety, "
        "pointing",
        _holomj("spec plan evaluation"),
    ),
    "holomj.tasks": (
        "robot tasks: success predicates on MuJoCo state and objects.json, task proposals",
        _holomj("spec"),
    ),
    "holomj.jobs": (
        "one module per user-facing job; the output folder (atomic I/O)",
        (
            *_holomj(
                "edit refinement atomic seeds data spec library layout retrieval plan compose"
            ),
            *_holomj("importers mjcf physics robots rendering formats evaluation tasks"),
            *_asset_pipeline("default_library :importers library_writer procedural"),
            *_asset_pipeline("procedural.articulated"),
        ),
    ),
    "holomj.envs": (
        "Gymnasium environments on scene folders: joint servo, task targets, scripted policy",
        _holomj("spec tasks robots jobs formats"),
    ),
    "holomj.batch": (
        "many jobs on a local worker pool or Ray, resumable",
        _holomj("atomic spec jobs"),
    ),
    "holomj.api": ("the Python API re-exported from holomj", _holomj("spec library jobs")),
    "holomj.cli": (
        "thin typer commands: parse options, call one job, print",
        _holomj("seeds spec jobs batch importers"),  # importers: the formats, for --format
    ),
    "holomj.__main__": ("python -m holomj", _holomj("cli")),
    "holomj": ("the package root: version and the lazy API", _holomj("api")),
    "asset_pipeline": ("the package root, the category data file", ()),
    "asset_pipeline:mesh": (
        "one mesh -> simulation-ready parts: load, frame, repair, CoACD, hulls, surfaces, mass",
        (*_holomj("spec"), "asset_pipeline"),
    ),
    "asset_pipeline:articulated_files": (
        "URDF and MJCF files -> the kinematic tree of an articulated asset",
        ("asset_pipeline:mesh",),
    ),
    "asset_pipeline.library_writer": (
        "writes asset libraries to disk, atomically and byte-deterministically",
        _holomj("atomic spec"),
    ),
    "asset_pipeline.collider_audit": (
        "how far an asset's visual surface reaches outside its colliders",
        _holomj("spec"),
    ),
    "asset_pipeline.thumbnails": (
        "thumbnails of an asset rendered headlessly",
        (*_holomj("spec library mjcf"), *_asset_pipeline("library_writer")),
    ),
    "asset_pipeline:importers": (
        "mesh, URDF/MJCF and objathor files -> library entries (ids, cache, process pool)",
        (
            *_holomj("atomic spec library"),
            *_asset_pipeline(":mesh :articulated_files library_writer thumbnails"),
            *_asset_pipeline("procedural.articulated"),
        ),
    ),
    "asset_pipeline.procedural": (
        "parametric furniture, fixtures and small objects: parts, assembly, OBJ files",
        (
            *_holomj("spec mjcf"),
            *_asset_pipeline("library_writer collider_audit"),
        ),
    ),
    "asset_pipeline.procedural.articulated": (
        "procedural furniture and appliances with doors, drawers and lids",
        (*_holomj("spec"), *_asset_pipeline("library_writer collider_audit procedural")),
    ),
    "asset_pipeline.default_library": (
        "the procedural default library: built on first use, rebuilt when generators change",
        (
            *_holomj("library"),
            *_asset_pipeline("library_writer procedural procedural.articulated"),
        ),
    ),
}
# a map name with a colon groups modules of a flat package: name -> its modules (and their trees)
GROUPS: dict[str, tuple[str, ...]] = {
    "asset_pipeline:mesh": _asset_pipeline(
        "load normalise repair decompose hulls objfile proximity surfaces physical annotate handles"
    ),
    "asset_pipeline:articulated_files": _asset_pipeline(
        "kinematics xml_tree urdf urdf_kinematics mjcf_import"
    ),
    "asset_pipeline:importers": _asset_pipeline(
        "import_records importer articulated_import articulated_bodies articulated_joints "
        "articulated_surfaces import_cache import_plan manage objathor objathor_files "
        "objathor_annotation objathor_mesh objathor_import"
    ),
}
# packages in the map before their first module exists: their imports are not held to be used
PLANNED: tuple[str, ...] = ()
# (importer, imported): a package under the first may import one under the second only inside
# functions (``import holomj`` stays light: no CoACD, trimesh or procedural generators)
LAZY_ONLY = (("holomj", "asset_pipeline"),)


@dataclass(frozen=True)
class PackageMap:
    """What the checker holds the code to (the module constants above, or a test's own)."""

    allowed: dict[str, tuple[str, tuple[str, ...]]]
    groups: dict[str, tuple[str, ...]] = field(default_factory=dict)
    foundation: tuple[str, ...] = ()
    planned: tuple[str, ...] = ()
    lazy_only: tuple[tuple[str, str], ...] = ()

    def package_of(self, module: str) -> str | None:
        """The map entry ``module`` belongs to: its group, else the longest matching package."""
        for group, members in self.groups.items():
            if any(_within(module, member) for member in members):
                return group
        found = [p for p in self.allowed if p not in self.groups and _within(module, p)]
        return max(found, key=len) if found else None

    def may_import(self, package: str) -> set[str]:
        """The packages ``package`` may import: its own line, itself and the foundation."""
        return {package, *self.allowed[package][1], *self.foundation}


MAP = PackageMap(ALLOWED, GROUPS, FOUNDATION, PLANNED, LAZY_ONLY)


def _within(module: str, package: str) -> bool:
    return module == package or module.startswith(package + ".")


@dataclass(frozen=True)
class Edge:
    """One import of one of our modules by another."""

    source: str
    target: str
    where: str  # file:line
    # "module" (module level), "function" (inside one), "type" (under TYPE_CHECKING) or "data"
    # (``resources.files("holomj.data")``: reads the data files of a package)
    kind: str


def find_modules(root: Path, tops: Iterable[str] = TOP_LEVEL) -> dict[str, Path]:
    """Every module of the packages ``tops`` under ``root``: dotted name -> file."""
    found = {}
    for top in tops:
        for path in sorted((root / top).rglob("*.py")):
            parts = path.relative_to(root).with_suffix("").parts
            found[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return found


def _is_type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def _resource_package(node: ast.Call) -> str | None:
    """The package a ``resources.files("package")`` call reads data files of, else None."""
    if not node.args:
        return None
    func, first = node.func, node.args[0]
    name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", None)
    if name == "files" and isinstance(first, ast.Constant) and isinstance(first.value, str):
        return first.value
    return None


def imports_of(name: str, path: Path, known: dict[str, Path], root: Path) -> list[Edge]:
    """The imports of modules in ``known`` that module ``name`` (file ``path``) makes."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    relative = path.relative_to(root)
    found: list[Edge] = []

    def resolve(dotted: str) -> str | None:
        while dotted and dotted not in known:
            dotted = dotted.rpartition(".")[0]
        return dotted or None

    def targets(node: ast.Import | ast.ImportFrom) -> Iterator[str | None]:
        if isinstance(node, ast.Import):
            yield from (resolve(alias.name) for alias in node.names)
            return
        base = node.module or ""
        if node.level:
            parts = package.split(".")[: len(package.split(".")) - node.level + 1]
            base = ".".join([*parts, base] if base else parts)
        for alias in node.names:
            yield resolve(f"{base}.{alias.name}") or resolve(base)

    def visit(nodes: Iterable[ast.AST], kind: str) -> None:
        for child in nodes:
            if isinstance(child, ast.Import | ast.ImportFrom):
                for target in targets(child):
                    if target and target != name:
                        found.append(Edge(name, target, f"{relative}:{child.lineno}", kind))
            if (
                isinstance(child, ast.Call)
                and (data := _resource_package(child))
                and (target := resolve(data)) == data
            ):
                found.append(Edge(name, target, f"{relative}:{child.lineno}", "data"))
            if isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
                visit(ast.iter_child_nodes(child), "function")
            elif isinstance(child, ast.If) and _is_type_checking(child) and kind == "module":
                visit(child.body, "type")
                visit(child.orelse, kind)
            else:
                visit(ast.iter_child_nodes(child), kind)

    visit(tree.body, "module")
    return found


def import_edges(root: Path, tops: Iterable[str] = TOP_LEVEL) -> tuple[list[Edge], dict[str, Path]]:
    """Every import among the modules of ``tops`` under ``root``, and those modules."""
    known = find_modules(root, tops)
    edges = [edge for name, path in known.items() for edge in imports_of(name, path, known, root)]
    return edges, known


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Every knot of ``graph``: its strongly connected components that hold a cycle, each sorted.

    Every cycle of the graph lies inside exactly one of them (Tarjan's algorithm, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    nodes = sorted(set(graph) | {n for targets in graph.values() for n in targets})
    for start in nodes:
        if start in index:
            continue
        work: list[tuple[str, Iterator[str]]] = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            nxt = next(successors, None)
            if nxt is not None:
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(graph.get(nxt, ())))))
                elif nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1 or node in graph.get(node, ()):
                    found.append(sorted(component))
    return sorted(found, key=lambda c: (-len(c), c))


def shortest_cycle(graph: dict[str, set[str]], start: str) -> list[str]:
    """A shortest cycle through ``start`` (first == last), or [] when there is none."""
    parent: dict[str, str] = {}
    frontier = [start]
    while frontier:
        following = []
        for node in frontier:
            for nxt in sorted(graph.get(node, ())):
                if nxt == start:
                    path = [node]
                    while path[-1] != start:
                        path.append(parent[path[-1]])
                    return [*reversed(path), start]
                if nxt not in parent:
                    parent[nxt] = node
                    following.append(nxt)
        frontier = following
    return []


def _cycle_problems(what: str, edges: list[tuple[str, str, Edge]]) -> list[str]:
    """One entry per knot of the graph ``edges`` (source, target, the import that makes it)."""
    graph: dict[str, set[str]] = defaultdict(set)
    for source, target, _ in edges:
        graph[source].add(target)
    problems = []
    for knot in cycles(graph):
        members = set(knot)
        inside = sorted(
            {(s, t, e.where, e.kind) for s, t, e in edges if s in members and t in members},
            key=lambda i: (i[2].rpartition(":")[0], int(i[2].rpartition(":")[2]), i[0], i[1]),
        )
        lines = [
            f"{what} import cycle through {len(knot)} {what}s: "
            + " -> ".join(shortest_cycle(graph, knot[0])),
            f"  {what}s: " + ", ".join(knot),
            *(f"  {where}: {s} -> {t} ({kind} level)" for s, t, where, kind in inside),
        ]
        problems.append("\n".join(lines))
    return problems


def check_edges(
    edges: list[Edge], known: dict[str, Path], pmap: PackageMap, root: Path
) -> list[str]:
    """Modules outside the map, map entries with no module, and imports the map does not allow."""
    problems = []
    packages = {name: pmap.package_of(name) for name in known}
    for name, owner in packages.items():
        if owner is None:
            problems.append(
                f"{known[name].relative_to(root)}: module {name} is in no package of the map"
            )
    present = set(packages.values())
    for package, (_, may) in pmap.allowed.items():
        if package not in present and package not in pmap.planned:
            problems.append(f"package map: {package} has no module (mark it planned or drop it)")
        if package in present and package in pmap.planned:
            problems.append(f"package map: {package} has modules now: drop it from PLANNED")
        for target in may:
            if target in pmap.foundation:
                problems.append(f"package map: {package} names {target}, which anyone may import")
            elif target not in pmap.allowed:
                problems.append(f"package map: {package} may import {target}, not in the map")
    for edge in edges:
        source, target_package = packages[edge.source], packages[edge.target]
        if source is None or target_package is None or source == target_package:
            continue
        if target_package not in pmap.may_import(source):
            problems.append(
                f"{edge.where}: {source} may not import {target_package} ({edge.target})"
            )
        for importer, imported in pmap.lazy_only:
            lazy_only = _within(source, importer) and not _within(source, imported)
            if lazy_only and _within(target_package, imported) and edge.kind == "module":
                problems.append(f"{edge.where}: {edge.target} imported outside a function")
    return problems


def unused_allowed(edges: list[Edge], pmap: PackageMap) -> list[str]:
    """The allowed imports of the map that no import of the code makes (planned ones excepted)."""
    used = set()
    for edge in edges:
        used.add((pmap.package_of(edge.source), pmap.package_of(edge.target)))
    return [
        f"package map: {package} may import {target}, but none of its modules does (drop it)"
        for package, (_, may) in pmap.allowed.items()
        for target in may
        if (package, target) not in used
        and package not in pmap.planned
        and target not in pmap.planned
    ]


def check_cycles(edges: list[Edge], pmap: PackageMap) -> list[str]:
    """Every module cycle and every package cycle, counting imports of every kind."""
    code = [edge for edge in edges if edge.kind != "data"]  # reading data files runs no code
    module_edges = [(e.source, e.target, e) for e in code]
    package_edges = []
    for edge in code:
        source, target = pmap.package_of(edge.source), pmap.package_of(edge.target)
        if source and target and source != target:
            package_edges.append((source, target, edge))
    return _cycle_problems("module", module_edges) + _cycle_problems("package", package_edges)


def _short(package: str) -> str:
    return package.removeprefix("holomj.")


def table_rows(pmap: PackageMap) -> list[str]:
    """The package map as the rows of a markdown table: package, what it owns, may import."""
    rows = []
    for package, (owns, may) in pmap.allowed.items():
        if package in pmap.foundation:
            continue
        names = ", ".join(f"`{_short(m)}`" for m in may) or "nothing of ours"
        planned = " (planned)" if package in pmap.planned else ""
        rows.append(f"| `{_short(package)}`{planned} | {owns} | {names} |")
    return rows


_ROW = re.compile(r"^\|\s*`(?P<package>[^`]+)`[^|]*\|[^|]*\|(?P<may>[^|]*)\|\s*$")


def check_doc(text: str, pmap: PackageMap, name: str = str(DOC)) -> list[str]:
    """Where the package table of ``text`` (the table of its section headed ``TABLE_HEADING``)
    differs from the map; the foundation packages are left out of it."""
    documented: dict[str, set[str]] = {}
    section = False
    for line in text.splitlines():
        if line.startswith("#"):
            section = line.lstrip("#").strip().lower().startswith(TABLE_HEADING.lower())
        elif section and (match := _ROW.match(line.strip())):
            documented[match["package"]] = set(re.findall(r"`([^`]+)`", match["may"]))
    expected = {
        _short(package): {_short(m) for m in may}
        for package, (_, may) in pmap.allowed.items()
        if package not in pmap.foundation
    }
    if not documented:
        return [
            f"{name}: no package table under a heading '{TABLE_HEADING}' "
            "(rows like | `library` | what it owns | `spec`, `data` |: see --map)"
        ]
    problems = []
    for package in sorted(expected.keys() - documented.keys()):
        problems.append(f"{name}: package {package} of the import map is not in the table")
    for package in sorted(documented.keys() - expected.keys()):
        problems.append(f"{name}: package {package} of the table is not in the import map")
    for package in sorted(expected.keys() & documented.keys()):
        if documented[package] != expected[package]:
            extra = ", ".join(sorted(documented[package] - expected[package])) or "-"
            missing = ", ".join(sorted(expected[package] - documented[package])) or "-"
            problems.append(
                f"{name}: {package} may import differs from the import map "
                f"(only in the doc: {extra}; only in the map: {missing})"
            )
    return problems


def check(root: Path = ROOT, pmap: PackageMap = MAP, tops: Iterable[str] = TOP_LEVEL) -> list[str]:
    """Every problem of the import graph under ``root``, one entry each (cycles span lines)."""
    edges, known = import_edges(root, tops)
    problems = check_edges(edges, known, pmap, root)
    problems += unused_allowed(edges, pmap)
    problems += check_cycles(edges, pmap)
    doc = root / DOC
    if doc.is_file():
        problems += check_doc(doc.read_text(encoding="utf-8"), pmap)
    else:
        problems.append(f"{DOC}: missing (it holds the package table)")
    return list(dict.fromkeys(problems))


def main() -> int:
    """Print the map (``--map``), or every problem; exit 1 when there is any."""
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--map", action="store_true", help="print the package map")
    args = parser.parse_args()
    if args.map:
        print("| package | what it owns | may import |\n|---|---|---|")
        print("\n".join(table_rows(MAP)))
        print(f"\nanyone may import: {', '.join(f'`{_short(p)}`' for p in MAP.foundation)}")
        return 0
    problems = check()
    for problem in problems:
        print(problem)
    print(f"import graph: {len(find_modules(ROOT))} modules, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
