#!/usr/bin/env bash
# Installs the npm `mikktspace` oracle into a cache folder once; later runs reuse it.
# Usage: install_oracle.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_oracle.sh CACHE_DIR}"
version="1.1.1"
manifest="$cache/node_modules/mikktspace/package.json"
if [ -f "$manifest" ] && grep -q "\"version\": \"$version\"" "$manifest"; then
  echo "mikktspace oracle $version cached in $cache"
  exit 0
fi
command -v npm >/dev/null || { echo "mikktspace oracle: npm not found (run .ci/setup)" >&2; exit 1; }
mkdir -p "$cache"
if ! npm install --prefix "$cache" --no-audit --no-fund --no-save "mikktspace@$version" >"$cache/npm-install.log" 2>&1; then
  echo "mikktspace oracle: 'npm install mikktspace@$version' failed; the npm registry is" \
       "needed once to fill the cache $cache (offline?). Log:" >&2
  tail -n 20 "$cache/npm-install.log" >&2
  exit 1
fi
echo "mikktspace oracle $version installed into $cache"
