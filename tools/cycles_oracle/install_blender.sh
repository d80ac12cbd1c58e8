#!/usr/bin/env bash
# Makes Blender (Cycles, its glTF importer, numpy for the importer) runnable for the
# Cycles oracle test through a wrapper, CACHE_DIR/blender, once; later runs reuse it.
# A system Blender (Debian's `blender`) whose Python imports numpy is used as it is.
# Otherwise Debian's packages that are not installed (blender, its libraries,
# python3-numpy) are fetched with `apt-get download` (no root needed) and unpacked with
# `dpkg -x` into CACHE_DIR/root; the wrapper points the loader and Python there. Without
# apt or the Debian mirror it exits 77, which CTest reports as skipped, and the oracle
# test skips too.
# Usage: install_blender.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_blender.sh CACHE_DIR}"
# Absolute: the wrapper names paths under the cache and runs from any directory.
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
wrapper="$cache/blender"
skip() { echo "Cycles oracle: $* -- skipped (install Debian's blender, or let apt reach its mirror)" >&2; exit 77; }
# Blender runs and its own Python imports numpy (the importer needs it).
works() { "$1" -b --factory-startup --python-exit-code 1 --python-expr 'import numpy' >/dev/null 2>&1; }
version() { "$1" -b --factory-startup --version 2>/dev/null | head -n 1; }

# Cached: made and checked by an earlier run (numpy was imported then); it still starts.
if [ -x "$wrapper" ] && cached=$(version "$wrapper") && [ -n "$cached" ]; then
  echo "Cycles oracle: $cached cached in $cache"
  exit 0
fi
mkdir -p "$cache"
system=$(command -v blender || true)
if [ -n "$system" ] && works "$system"; then
  printf '#!/bin/sh\nexec %q "$@"\n' "$system" >"$wrapper"
  chmod +x "$wrapper"
  echo "Cycles oracle: the system's $(version "$system")"
  exit 0
fi
command -v apt-get >/dev/null && command -v dpkg >/dev/null || skip "no apt-get/dpkg"

start=$(date +%s)
debs="$cache/debs"
root="$cache/root"
rm -rf "$debs" "$root"
mkdir -p "$debs" "$root"
# What installing would add (a simulation needs no root): blender and its libraries
# less what is installed, and numpy for the glTF importer.
packages=$(apt-get -s install --no-install-recommends blender python3-numpy 2>/dev/null |
           awk '/^Inst /{print $2}') || true
[ -n "$packages" ] || skip "apt-get cannot resolve blender (not a Debian 12 system?)"
# shellcheck disable=SC2086
(cd "$debs" && apt-get download $packages >"$cache/apt-download.log" 2>&1) ||
  { tail -n 5 "$cache/apt-download.log" >&2; skip "apt-get download failed (offline?)"; }
for deb in "$debs"/*.deb; do dpkg -x "$deb" "$root"; done
rm -rf "$debs"
# The unpacked blender, or the system's where only numpy was missing.
if [ -x "$root/usr/bin/blender" ]; then binary="$root/usr/bin/blender"
elif [ -n "$system" ]; then binary="$system"
else skip "the blender package unpacked no usr/bin/blender"; fi

# Every folder of the unpacked tree that holds a shared library goes on the loader path.
libs=$(find "$root" -name '*.so*' -type f -printf '%h\n' | sort -u | tr '\n' ':')
{
  echo '#!/bin/sh'
  echo "# Runs Blender with what $(basename "$0") unpacked into $root."
  printf 'export LD_LIBRARY_PATH=%q${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}\n' "${libs%:}"
  printf 'export PYTHONPATH=%q${PYTHONPATH:+:$PYTHONPATH}\n' "$root/usr/lib/python3/dist-packages"
  # blender-data (scripts, the glTF importer) unpacked here when it was not installed.
  if [ -d "$root/usr/share/blender/scripts" ]; then
    printf 'export BLENDER_SYSTEM_SCRIPTS=%q\n' "$root/usr/share/blender/scripts"
    printf 'export BLENDER_SYSTEM_DATAFILES=%q\n' "$root/usr/share/blender/datafiles"
  fi
  printf 'exec %q "$@"\n' "$binary"
} >"$wrapper"
chmod +x "$wrapper"
works "$wrapper" || { rm -f "$wrapper"; skip "the unpacked blender does not start or its Python lacks numpy"; }
echo "Cycles oracle: $(version "$wrapper") unpacked into $cache from $(echo "$packages" | wc -w)" \
     "packages in $(( $(date +%s) - start )) s"
