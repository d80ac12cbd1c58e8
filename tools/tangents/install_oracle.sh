#!/usr/bin/env bash
# Installs the npm `mikktspace` oracle into a cache folder once; later runs reuse it.
# Usage: install_oracle.sh CACHE_DIR
exec "$(dirname "$0")/../npm/install_npm_package.sh" "${1:?usage: install_oracle.sh CACHE_DIR}" \
  mikktspace@1.1.1
