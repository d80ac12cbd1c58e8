#!/usr/bin/env bash
# Installs the KHR_animation_pointer oracle's npm packages into a cache folder once; later
# runs reuse it: three 0.170.0 (the motion oracle's version) and Needle's GLTFLoader
# plugin @needle-tools/three-animation-pointer 1.0.7 (MIT licence; peer dependency
# three >= 0.165). Both go in with one npm install: a second `npm install --no-save`
# into the same prefix would prune the first.
# Usage: install_three_pointer.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_three_pointer.sh CACHE_DIR}"
here="$(dirname "$0")"
three='"version": "0.170.0"'
if ! grep -qs "$three" "$cache/node_modules/three/package.json"; then
  rm -rf "$cache/node_modules/@needle-tools" # reinstall both together
fi
"$here/../npm_cache_install.sh" @needle-tools/three-animation-pointer 1.0.7 "$cache" \
  "KHR_animation_pointer oracle (three, @needle-tools/three-animation-pointer)" three@0.170.0
grep -qs "$three" "$cache/node_modules/three/package.json" ||
  { echo "pointer oracle: three 0.170.0 missing from $cache" >&2; exit 1; }
