#!/usr/bin/env bash
# Installs the npm `mikktspace` oracle into a cache folder once; later runs reuse it.
# Usage: install_oracle.sh CACHE_DIR
set -euo pipefail
exec "$(dirname "$0")/../npm_cache_install.sh" mikktspace 1.1.1 "${1:?usage: install_oracle.sh CACHE_DIR}" "mikktspace oracle"
