"""Build holomj's procedural default asset library into a folder.

Usage: python scripts/build_default_library.py --out FOLDER

The output is byte-deterministic for a given DEFAULT_LIBRARY_VERSION (a hash of the generator
sources); holomj builds the same library on first use, so nothing needs to be committed.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from asset_pipeline.procedural import DEFAULT_LIBRARY_VERSION, build_default_library


def main() -> None:
    """Parse the arguments, write the library and report what was written."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="library folder to (over)write")
    args = parser.parse_args()
    start = time.perf_counter()
    root = build_default_library(args.out, overwrite=True)
    elapsed = time.perf_counter() - start
    files = [p for p in root.rglob("*") if p.is_file()]
    assets = sum(1 for p in files if p.name == "asset.json")
    size = sum(p.stat().st_size for p in files)
    print(
        f"wrote {root}: version {DEFAULT_LIBRARY_VERSION}, {assets} assets, {len(files)} files, "
        f"{size / 1024:.1f} KiB in {elapsed:.2f} s"
    )


if __name__ == "__main__":
    main()
