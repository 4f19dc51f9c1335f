#!/usr/bin/env bash
# Set up holomj on a fresh Debian/Ubuntu machine: the Mesa GL libraries headless rendering needs
# (and, with the dev extra, Chromium for the report page's browser test) when run as root with
# apt, then a virtual environment in .venv with holomj installed.
# Usage: bash scripts/setup.sh [EXTRAS]     e.g. bash scripts/setup.sh dev
set -euo pipefail
cd "$(dirname "$0")/.."

extras="${1:-}"
python="${PYTHON:-python3}"

if command -v apt-get >/dev/null 2>&1 && [ "$(id -u)" = 0 ]; then
  packages="libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6"
  # the dev extra's tests open report.html in a headless browser
  case ",$extras," in *,dev,*) packages="$packages chromium" ;; esac
  missing=""
  for pkg in $packages; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing="$missing $pkg"
  done
  if [ -n "$missing" ]; then
    echo "setup: installing system packages:$missing"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $missing >/dev/null
  fi
fi

if [ ! -x .venv/bin/python ]; then
  "$python" -m venv .venv
fi
.venv/bin/python -m pip install -q --upgrade pip >/dev/null
spec="."
if [ -n "$extras" ]; then spec=".[$extras]"; fi
.venv/bin/python -m pip install -q -e "$spec" 2>&1 | grep -v -E "^(WARNING: Location|  |$)" || true
# The Panda for --robot panda (and its tests): holomj reads only its MJCF and meshes; its
# dependencies pin an old mujoco, so it is installed without them (pyproject cannot say so).
case ",$extras," in *,dev,*)
  .venv/bin/python -m pip install -q --no-deps dm-robotics-panda 2>&1 | grep -v -E "^(WARNING: Location|  |$)" || true ;;
esac
.venv/bin/python -c "import holomj, mujoco; print(f'setup: holomj {holomj.__version__}, mujoco {mujoco.__version__}')"
