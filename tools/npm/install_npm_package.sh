#!/usr/bin/env bash
# Installs pinned npm packages (test-time reference tools: oracles, encoders,
# compressors) into a cache folder once; later runs reuse it. Shared by every
# CTest fixture that needs an npm tool, so the caching and the offline message are
# written once. Usage:
#   install_npm_package.sh CACHE_DIR [--ignore-scripts] NAME@VERSION...
set -euo pipefail
cache="${1:?usage: install_npm_package.sh CACHE_DIR [--ignore-scripts] NAME@VERSION...}"
shift
flags=()
if [ "${1:-}" = "--ignore-scripts" ]; then
  flags+=(--ignore-scripts)
  shift
fi
[ $# -gt 0 ] || { echo "install_npm_package.sh: no NAME@VERSION given" >&2; exit 2; }
missing=()
for spec in "$@"; do
  name="${spec%@*}"
  version="${spec##*@}"
  manifest="$cache/node_modules/$name/package.json"
  if [ -f "$manifest" ] && grep -q "\"version\": \"$version\"" "$manifest"; then
    echo "$name $version cached in $cache"
  else
    missing+=("$spec")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0
command -v npm >/dev/null || { echo "${missing[*]}: npm not found (run .ci/setup)" >&2; exit 1; }
mkdir -p "$cache"
# All of them in one call: a --no-save install prunes packages it was not given.
if ! npm install --prefix "$cache" --no-audit --no-fund --no-save "${flags[@]}" "$@" \
     >"$cache/npm-install.log" 2>&1; then
  echo "'npm install ${missing[*]}' failed; the npm registry is needed once to fill the" \
       "cache $cache (offline?). Log:" >&2
  tail -n 20 "$cache/npm-install.log" >&2
  exit 1
fi
echo "${missing[*]} installed into $cache"
