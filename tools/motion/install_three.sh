#!/usr/bin/env bash
# Installs the npm `three` oracle (three.js) into a cache folder once; later runs reuse it.
# Usage: install_three.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_three.sh CACHE_DIR}"
version="0.170.0"
manifest="$cache/node_modules/three/package.json"
if [ -f "$manifest" ] && grep -q "\"version\": \"$version\"" "$manifest"; then
  echo "three.js oracle $version cached in $cache"
  exit 0
fi
command -v npm >/dev/null || { echo "three.js oracle: npm not found (run .ci/setup)" >&2; exit 1; }
mkdir -p "$cache"
if ! npm install --prefix "$cache" --no-audit --no-fund --no-save "three@$version" >"$cache/npm-install.log" 2>&1; then
  echo "three.js oracle: 'npm install three@$version' failed; the npm registry is" \
       "needed once to fill the cache $cache (offline?). Log:" >&2
  tail -n 20 "$cache/npm-install.log" >&2
  exit 1
fi
echo "three.js oracle $version installed into $cache"
