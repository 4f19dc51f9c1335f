#!/usr/bin/env bash
# Set up with the dev extra, lint, type-check, check the import map and code size, and run the
# whole test suite (CI runs this).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh dev
.venv/bin/ruff check holomj asset_pipeline mjcf_templates scripts tests
.venv/bin/mypy                                # basic checking of holomj and asset_pipeline
.venv/bin/python scripts/check_imports.py     # the package map: no cycle, no unused allowed edge
.venv/bin/python scripts/check_code_size.py   # module and function size limits
.venv/bin/python -m pytest -n 2 -q "$@"
