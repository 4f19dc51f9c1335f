"""Regenerate holomj's procedural default asset library in holomj/data/default_library/.

Usage: python scripts/build_default_library.py [--out FOLDER]

The output is byte-deterministic; the generated files are committed, and
tests/asset_pipeline/test_procedural.py checks that they match this generator.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from asset_pipeline.procedural import build_default_library

REPO = Path(__file__).resolve().parent.parent
DEFAULT_OUT = REPO / "holomj" / "data" / "default_library"


def main() -> None:
    """Parse the arguments and write the library."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="library folder to write")
    args = parser.parse_args()
    root = build_default_library(args.out, overwrite=True)
    files = [p for p in root.rglob("*") if p.is_file()]
    size = sum(p.stat().st_size for p in files)
    print(f"wrote {root}: {len(files)} files, {size / 1024:.1f} KiB")


if __name__ == "__main__":
    main()
