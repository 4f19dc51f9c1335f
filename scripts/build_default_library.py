"""Build holomj's procedural default asset library into a folder.

Usage: python scripts/build_default_library.py --out FOLDER [--summary SUMMARY.json]

The output is byte-deterministic for a given DEFAULT_LIBRARY_VERSION (a hash of the generator
sources); holomj builds the same library on first use, so nothing needs to be committed. The
report gives the size on disk (shared textures are hard links: each counted once) and the
collider audit (the largest distance of a visual surface outside its colliders, per category);
``--summary`` also writes that audit as JSON.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from asset_pipeline.collider_audit import gap_summary
from asset_pipeline.procedural import DEFAULT_LIBRARY_VERSION, build_default_library
from holomj.library.store import AssetLibrary


def disk_bytes(root: Path) -> tuple[int, int]:
    """(number of files, bytes) under ``root``, a file with several hard links counted once."""
    seen: set[tuple[int, int]] = set()
    files = size = 0
    for path in root.rglob("*"):
        if not path.is_file():
            continue
        files += 1
        stat = path.stat()
        if (stat.st_dev, stat.st_ino) not in seen:
            seen.add((stat.st_dev, stat.st_ino))
            size += stat.st_size
    return files, size


def main() -> None:
    """Parse the arguments, write the library and report what was written."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="library folder to (over)write")
    parser.add_argument("--summary", type=Path, help="write the collider audit here (JSON)")
    args = parser.parse_args()
    start = time.perf_counter()
    root = build_default_library(args.out, overwrite=True)
    elapsed = time.perf_counter() - start
    files, size = disk_bytes(root)
    library = AssetLibrary.open(root)
    audit = gap_summary(library.get(i).meta for i in library.ids())
    print(
        f"wrote {root}: version {DEFAULT_LIBRARY_VERSION}, {len(library.ids())} assets, "
        f"{files} files, {size / 1024:.1f} KiB in {elapsed:.2f} s"
    )
    print(
        f"collider audit: worst gap {audit['worst_mm']:.1f} mm, "
        f"{len(audit['over_limit'])} assets over {audit['limit_mm']:.0f} mm"  # type: ignore[arg-type]
    )
    if args.summary is not None:
        args.summary.parent.mkdir(parents=True, exist_ok=True)
        args.summary.write_text(json.dumps(audit, indent=2, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
