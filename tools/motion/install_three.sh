#!/usr/bin/env bash
# Installs the npm `three` oracle (three.js) into a cache folder once; later runs reuse it.
# Usage: install_three.sh CACHE_DIR
set -euo pipefail
exec "$(dirname "$0")/../npm_cache_install.sh" three 0.170.0 "${1:?usage: install_three.sh CACHE_DIR}" "three.js oracle"
