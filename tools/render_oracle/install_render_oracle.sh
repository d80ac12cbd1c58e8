#!/usr/bin/env bash
# Installs the three.js render oracle's npm packages (three, puppeteer-core) into a cache
# folder once; later runs reuse it. Chromium itself is Debian's (/usr/bin/chromium,
# .ci/setup): puppeteer-core downloads no browser.
# Usage: install_render_oracle.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_render_oracle.sh CACHE_DIR}"
here="$(dirname "$0")"
"$here/../npm_cache_install.sh" three 0.170.0 "$cache" "three.js render oracle"
"$here/../npm_cache_install.sh" puppeteer-core 25.16.0 "$cache" "puppeteer-core (render oracle)"
command -v /usr/bin/chromium >/dev/null || { echo "render oracle: /usr/bin/chromium missing (run .ci/setup)" >&2; exit 1; }
