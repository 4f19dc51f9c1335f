"""Check the size limits of holomj's and asset_pipeline's modules and functions.

Limits (the codebase's house rules): no module over 600 lines and at most 20 over 400; no
function over 120 lines and at most 10 over 80. Lines are physical lines of the file; a
function's length runs from its ``def`` (decorators excluded) to its last line.

    python scripts/check_code_size.py            # exit 1 and the offenders when a limit is broken
    python scripts/check_code_size.py --list     # every module over 400 and function over 80 lines

CI runs it (scripts/test.sh).
"""

from __future__ import annotations

import argparse
import ast
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("holomj", "asset_pipeline")
MODULE_MAX, MODULE_LONG, MODULES_LONG_MAX = 600, 400, 20
FUNCTION_MAX, FUNCTION_LONG, FUNCTIONS_LONG_MAX = 120, 80, 10


def measure() -> tuple[list[tuple[int, str]], list[tuple[int, str]]]:
    """Every module over MODULE_LONG lines and every function over FUNCTION_LONG, longest first."""
    modules: list[tuple[int, str]] = []
    functions: list[tuple[int, str]] = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            text = path.read_text(encoding="utf-8")
            rel = str(path.relative_to(ROOT))
            lines = text.count("\n")
            if lines > MODULE_LONG:
                modules.append((lines, rel))
            for node in ast.walk(ast.parse(text, filename=rel)):
                if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                    length = (node.end_lineno or node.lineno) - node.lineno + 1
                    if length > FUNCTION_LONG:
                        functions.append((length, f"{rel}:{node.lineno}:{node.name}"))
    return sorted(modules, reverse=True), sorted(functions, reverse=True)


def problems(modules: list[tuple[int, str]], functions: list[tuple[int, str]]) -> list[str]:
    """One line per broken limit."""
    found = [f"{p}: {n} lines (at most {MODULE_MAX})" for n, p in modules if n > MODULE_MAX]
    found += [f"{p}: {n} lines (at most {FUNCTION_MAX})" for n, p in functions if n > FUNCTION_MAX]
    if len(modules) > MODULES_LONG_MAX:
        found.append(
            f"{len(modules)} modules over {MODULE_LONG} lines (at most {MODULES_LONG_MAX})"
        )
    if len(functions) > FUNCTIONS_LONG_MAX:
        found.append(
            f"{len(functions)} functions over {FUNCTION_LONG} lines (at most {FUNCTIONS_LONG_MAX})"
        )
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--list", action="store_true", help="list every long module and function")
    args = parser.parse_args()
    modules, functions = measure()
    if args.list:
        for n, p in modules:
            print(f"module {n:5d} {p}")
        for n, p in functions:
            print(f"function {n:3d} {p}")
    found = problems(modules, functions)
    for line in found:
        print(line)
    print(
        f"code size: {len(modules)} modules over {MODULE_LONG} lines, "
        f"{len(functions)} functions over {FUNCTION_LONG} lines, {len(found)} problem(s)"
    )
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
