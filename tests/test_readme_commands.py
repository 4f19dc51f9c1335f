"""The README's command blocks run as written, one after the other, from a fresh folder: the
"Using it" block, and the blocks of "For robot learning" (a prompt to a checked task)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
ACTIVATE = "source .venv/bin/activate"


def bash_blocks(section: str) -> list[str]:
    """The bash blocks of the README's section titled ``section`` (up to the next ``## ``)."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    body = readme.split(f"\n## {section}\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```bash\n(.*?)```", body, re.S)
    assert blocks, f"README's {section!r} section has no bash block"
    return blocks


def run_as_written(script: str, folder: Path) -> subprocess.CompletedProcess[str]:
    """Run ``script`` with bash in ``folder``, laid out like the repository's root (examples/
    and a .venv whose activate script puts this interpreter's holomj first on PATH)."""
    (folder / "examples").symlink_to(ROOT / "examples")
    venv_bin = folder / ".venv" / "bin"
    venv_bin.mkdir(parents=True)
    (venv_bin / "activate").write_text(
        f'export PATH="{Path(sys.executable).parent}:$PATH"\n', encoding="utf-8"
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run(
        ["bash", "-c", "set -euxo pipefail\n" + script],
        cwd=folder,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )


def test_using_it_starts_by_activating_the_quick_starts_environment() -> None:
    lines = [line for line in bash_blocks("Using it")[0].splitlines() if line.strip()]
    assert lines[0] == ACTIVATE
    assert all(line.startswith("holomj ") for line in lines[1:])


@pytest.mark.slow
def test_every_using_it_command_runs_as_written(tmp_path: Path, default_library: object) -> None:
    run = run_as_written(bash_blocks("Using it")[0], tmp_path)
    assert run.returncode == 0, (run.stdout + run.stderr)[-3000:]
    for made in ("music/scene.xml", "house/report.json", "house/eval.json", "house2/scene.xml"):
        assert (tmp_path / "out" / made).is_file(), made
    assert (tmp_path / "out" / "scene.schema.json").stat().st_size > 1000


@pytest.mark.slow
def test_the_robot_learning_path_runs_as_written(tmp_path: Path, default_library: object) -> None:
    blocks = bash_blocks("For robot learning")
    assert blocks[0].startswith(ACTIVATE)
    run = run_as_written("\n".join(blocks), tmp_path)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    # the README's comments say what a user sees: a random step fails, the scripted policy succeeds
    assert "a random step: 0.0 False" in run.stdout, out[-3000:]
    assert "success=True" in run.stdout, out[-3000:]
    kitchen = tmp_path / "out" / "kitchen"
    assert (kitchen / "tasks.json").is_file()
    assert (kitchen / "export" / "scene.mjb").is_file()
    assert len(list((tmp_path / "out" / "kitchen_variants").glob("variant_*"))) == 3
