#!/usr/bin/env bash
# The main job on a fresh machine: set up, generate a scene from a prompt offline with the
# embedded default asset library (plan, retrieve, lay out, drop small objects, validate, render),
# then summarise it. Open out/example/report.html to look at it.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
.venv/bin/holomj generate "a two-bedroom apartment with a home office" -o out/example --seed 7 --overwrite
.venv/bin/holomj info out/example
