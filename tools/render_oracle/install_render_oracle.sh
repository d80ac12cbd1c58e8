#!/usr/bin/env bash
# Installs the three.js render oracle's npm packages (three, puppeteer-core) into a cache
# folder once; later runs reuse it. Chromium itself is Debian's (/usr/bin/chromium,
# .ci/setup): puppeteer-core downloads no browser. Both packages go in with one npm
# install: a second `npm install --no-save` into the same prefix would prune the first.
# Usage: install_render_oracle.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_render_oracle.sh CACHE_DIR}"
here="$(dirname "$0")"
three='"version": "0.170.0"'
if ! grep -qs "$three" "$cache/node_modules/three/package.json"; then
  rm -rf "$cache/node_modules/puppeteer-core" # reinstall both together
fi
"$here/../npm_cache_install.sh" puppeteer-core 25.16.0 "$cache" "render oracle (puppeteer-core, three)" three@0.170.0
grep -qs "$three" "$cache/node_modules/three/package.json" ||
  { echo "render oracle: three 0.170.0 missing from $cache" >&2; exit 1; }
[ -x /usr/bin/chromium ] || { echo "render oracle: /usr/bin/chromium missing (run .ci/setup)" >&2; exit 1; }
