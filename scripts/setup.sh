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
# pip runs quietly and its noise (index warnings, indented detail lines) is filtered out, but a
# failed install prints everything pip said and stops the setup: a missing extra must not turn
# tests into skips while CI stays green.
pip_install() {
  local log status=0
  log="$(mktemp)"
  .venv/bin/python -m pip install -q "$@" >"$log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    cat "$log" >&2
    rm -f "$log"
    echo "setup: 'pip install $*' failed with exit code $status" >&2
    exit "$status"
  fi
  grep -v -E "^(WARNING: Location|  |$)" "$log" || true  # grep exits 1 when nothing is left
  rm -f "$log"
}

pip_install --upgrade pip
spec="."
if [ -n "$extras" ]; then spec=".[$extras]"; fi
pip_install -e "$spec"
# The Panda for --robot panda (and its tests): holomj reads only its MJCF and meshes; its
# dependencies pin an old mujoco, so it is installed without them (pyproject cannot say so).
case ",$extras," in *,dev,*) pip_install --no-deps dm-robotics-panda ;; esac
.venv/bin/python -c "import holomj, mujoco; print(f'setup: holomj {holomj.__version__}, mujoco {mujoco.__version__}')"
