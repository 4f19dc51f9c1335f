"""The README's "Using it" commands run as written, one after the other, from a fresh folder."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
ACTIVATE = "source .venv/bin/activate"


def using_it_commands() -> list[str]:
    """The command lines of the README's first bash block under "## Using it"."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme.split("\n## Using it\n", 1)[1]
    block = re.search(r"```bash\n(.*?)```", section, re.S)
    assert block, "README's 'Using it' section has no bash block"
    return [line for line in block.group(1).splitlines() if line.strip()]


def test_the_block_starts_by_activating_the_quick_starts_environment() -> None:
    commands = using_it_commands()
    assert commands[0] == ACTIVATE
    assert all(line.startswith("holomj ") for line in commands[1:])


@pytest.mark.slow
def test_every_using_it_command_runs_as_written(tmp_path: Path, default_library: object) -> None:
    commands = using_it_commands()
    # a copy of the repository's root as the README expects it: examples/ and .venv/bin
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    venv_bin = tmp_path / ".venv" / "bin"
    venv_bin.mkdir(parents=True)
    (venv_bin / "activate").write_text(
        f'export PATH="{Path(sys.executable).parent}:$PATH"\n', encoding="utf-8"
    )
    script = "set -euo pipefail\n" + "\n".join(
        f'echo "+ {line.split("#")[0].strip()}" >&2\n{line}' for line in commands
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    run = subprocess.run(
        ["bash", "-c", script], cwd=tmp_path, env=env, capture_output=True, text=True
    )
    tail = (run.stdout + run.stderr)[-3000:]
    assert run.returncode == 0, tail
    for made in ("music/scene.xml", "house/report.json", "house/eval.json", "house2/scene.xml"):
        assert (tmp_path / "out" / made).is_file(), made
    assert (tmp_path / "out" / "scene.schema.json").stat().st_size > 1000
