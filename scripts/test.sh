#!/usr/bin/env bash
# Set up with the dev extra, lint, and run the whole test suite (CI runs this).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh dev
.venv/bin/ruff check holomj asset_pipeline mjcf_templates scripts tests
.venv/bin/python scripts/check_imports.py
.venv/bin/python -m pytest -n 2 -q "$@"
