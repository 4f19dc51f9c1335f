#!/usr/bin/env bash
# Rebuild holomj/rendering/vendor/three-viewer.min.js: the parts of three.js the report page's 3D
# view uses (core, GLTFLoader, OrbitControls), bundled and minified into one classic script that
# defines the global HOLOMJ_THREE, so the page works offline from file:// (no ES module imports).
# Needs node and npm (the npm registry); run it when upgrading three.js. The output is committed
# and shipped as package data with three.js's MIT licence (vendor/three.LICENSE.txt).
# Usage: bash scripts/build_viewer_vendor.sh [THREE_VERSION]
set -euo pipefail
cd "$(dirname "$0")/.."
version="${1:-0.187.0}"
esbuild_version="0.28.2"
vendor="$PWD/holomj/rendering/vendor"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
npm init -y >/dev/null
npm install --no-audit --no-fund --silent "three@$version" "esbuild@$esbuild_version" >/dev/null
cat > entry.js <<'JS'
export {
  AmbientLight, Box3, Box3Helper, Color, DirectionalLight, DoubleSide, HemisphereLight,
  MathUtils, MeshLambertMaterial, NeutralToneMapping, PerspectiveCamera, Raycaster,
  SRGBColorSpace, Scene, Vector2, Vector3, WebGLRenderer, REVISION,
} from 'three';
export { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
export { OrbitControls } from 'three/addons/controls/OrbitControls.js';
JS
npx esbuild entry.js --bundle --minify --format=iife --global-name=HOLOMJ_THREE \
  --legal-comments=none --target=es2020 --outfile=bundle.js --log-level=warning
{
  echo "/* three.js r$(echo "$version" | cut -d. -f2) (core, GLTFLoader, OrbitControls), MIT licence: three.LICENSE.txt."
  echo "   Built by scripts/build_viewer_vendor.sh with esbuild ${esbuild_version}. */"
  cat bundle.js
} > "$vendor/three-viewer.min.js"
cp node_modules/three/LICENSE "$vendor/three.LICENSE.txt"
echo "wrote $vendor/three-viewer.min.js ($(wc -c < "$vendor/three-viewer.min.js") bytes)"
