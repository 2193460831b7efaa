#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Rebuilds the viewer's vendored 3-D library (docs/viewing-runs.md, "Why three.js is vendored"):
# three.js and its OrbitControls from npm, bundled and minified by esbuild into one ES module,
# apps/python/view/web/vendor/three.bundle.min.js, with three.js's MIT licence
# beside it. Needs node and npm and the npm registry; nothing else in the build does.
#   THREE_VERSION  the three.js release (default below); commit the two files it writes.
set -euo pipefail
cd "$(dirname "$0")/.."
version=${THREE_VERSION:-0.187.0}
esbuild_version=0.25.12
vendor=apps/python/view/web/vendor
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

(cd "$work" && npm init -y >/dev/null &&
  npm install --silent --no-audit --no-fund "three@$version" "esbuild@$esbuild_version" >/dev/null)
cat >"$work/entry.js" <<'JS'
export * from "three";
export { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
JS
banner="/* three.js $version (https://threejs.org, MIT licence: three-LICENSE.txt) with OrbitControls; bundled by scripts/vendor-three.sh */"
"$work/node_modules/.bin/esbuild" "$work/entry.js" --bundle --minify --format=esm --target=es2020 \
  --legal-comments=none --banner:js="$banner" --outfile="$vendor/three.bundle.min.js" --log-level=warning
cp "$work/node_modules/three/LICENSE" "$vendor/three-LICENSE.txt"
echo "vendor-three: $vendor/three.bundle.min.js ($(wc -c <"$vendor/three.bundle.min.js") bytes), three.js $version"
