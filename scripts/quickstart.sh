#!/usr/bin/env bash
# The main job on a fresh machine: set up, compile the bundled example house, summarise it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
.venv/bin/holomj compile examples/procthor_house.json -o out/example_house --overwrite
.venv/bin/holomj info out/example_house
