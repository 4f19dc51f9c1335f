"""Benchmark: load time of a scene folder's ``scene.xml`` against its single-file packages.

Packs the folder (``holomj pack``: ``scene.mjb``, MuJoCo's binary model, and ``scene.zip``, the
folder in one archive) into a temporary folder, then measures the median wall time over
``--repeats`` loads of each: ``MjModel.from_xml_path(scene.xml)``,
``MjModel.from_binary_path(scene.mjb)`` and ``load_package(scene.zip)`` (read, unzip in memory,
compile). Writes JSON::

    python scripts/bench_load.py OUT --out bench_results/load.json [--repeats 11]
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import mujoco

from holomj.formats.package import load_package
from holomj.jobs.pack import pack_folder


def _median_s(load: Callable[[], Any], repeats: int) -> float:
    times = []
    for _ in range(repeats):
        clock = time.perf_counter()
        load()
        times.append(time.perf_counter() - clock)
    return statistics.median(times)


def measure(folder: Path, repeats: int) -> dict[str, Any]:
    """Median load seconds of scene.xml, scene.mjb and scene.zip, their sizes and speed-ups."""
    with tempfile.TemporaryDirectory() as tmp:
        packed = pack_folder(folder, "all", Path(tmp))
        mjb, archive = packed.files["mjb"], packed.files["zip"]
        model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
        loads = {
            "xml": _median_s(
                lambda: mujoco.MjModel.from_xml_path(str(folder / "scene.xml")), repeats
            ),
            "mjb": _median_s(lambda: mujoco.MjModel.from_binary_path(mjb), repeats),
            "zip": _median_s(lambda: load_package(archive), repeats),
        }
    return {
        "folder": str(folder),
        "repeats": repeats,
        "model": {"nbody": model.nbody, "ngeom": model.ngeom, "nmesh": model.nmesh},
        "median_load_s": {key: round(value, 5) for key, value in loads.items()},
        "speedup_vs_xml": {key: round(loads["xml"] / value, 2) for key, value in loads.items()},
        "bytes": packed.bytes,
        "platform": {
            "python": sys.version.split()[0],
            "mujoco": mujoco.__version__,
            "machine": platform.machine(),
        },
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="a scene folder (holomj generate/compile)")
    parser.add_argument("--out", type=Path, help="write the JSON here (default: print it)")
    parser.add_argument("--repeats", type=int, default=11)
    args = parser.parse_args(argv)
    result = measure(args.folder, max(1, args.repeats))
    text = json.dumps(result, indent=2)
    if args.out:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(text + "\n")
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
