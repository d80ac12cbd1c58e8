#!/usr/bin/env bash
# Installs one npm package at one version into a cache folder once; later runs reuse it.
# Test-time oracles (tools/tangents, tools/motion) are installed this way by CTest
# fixtures: the npm registry is needed the first time only.
# Usage: npm_cache_install.sh PACKAGE VERSION CACHE_DIR LABEL [NPM_INSTALL_ARGS...]
set -euo pipefail
package="${1:?usage: npm_cache_install.sh PACKAGE VERSION CACHE_DIR LABEL}"
version="${2:?}"
cache="${3:?}"
label="${4:-$package oracle}"
shift $(( $# < 4 ? $# : 4 ))
manifest="$cache/node_modules/$package/package.json"
if [ -f "$manifest" ] && grep -q "\"version\": \"$version\"" "$manifest"; then
  echo "$label $version cached in $cache"
  exit 0
fi
command -v npm >/dev/null || { echo "$label: npm not found (run .ci/setup)" >&2; exit 1; }
mkdir -p "$cache"
if ! npm install --prefix "$cache" --no-audit --no-fund --no-save "$@" "$package@$version" >"$cache/npm-install.log" 2>&1; then
  echo "$label: 'npm install $package@$version' failed; the npm registry is" \
       "needed once to fill the cache $cache (offline?). Log:" >&2
  tail -n 20 "$cache/npm-install.log" >&2
  exit 1
fi
echo "$label $version installed into $cache"
