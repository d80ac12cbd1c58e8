#!/usr/bin/env bash
# Makes Blender (Cycles, its glTF importer) runnable for the Cycles oracle test through a
# wrapper, CACHE_DIR/blender, once; later runs reuse it. A system Blender (Debian's
# `blender`) is used as it is. Otherwise Debian's packages that are not installed
# (blender, its libraries, python3-numpy) are fetched with `apt-get download` (no root
# needed) and unpacked with `dpkg -x` into CACHE_DIR/root; the wrapper points the
# loader and Python there. Without apt or the Debian mirror it exits 77, which CTest
# reports as skipped, and the oracle test skips too.
# Usage: install_blender.sh CACHE_DIR
set -euo pipefail
cache="${1:?usage: install_blender.sh CACHE_DIR}"
wrapper="$cache/blender"
skip() { echo "Cycles oracle: $* -- skipped (install Debian's blender, or let apt reach its mirror)" >&2; exit 77; }

if [ -x "$wrapper" ] && version=$("$wrapper" -b --factory-startup --version 2>/dev/null); then
  echo "Cycles oracle: $(echo "$version" | head -n 1) cached in $cache"
  exit 0
fi
mkdir -p "$cache"
if command -v blender >/dev/null && python3 -c 'import numpy' 2>/dev/null; then
  printf '#!/bin/sh\nexec %q "$@"\n' "$(command -v blender)" >"$wrapper"
  chmod +x "$wrapper"
  echo "Cycles oracle: the system's $(blender -b --factory-startup --version 2>/dev/null | head -n 1)"
  exit 0
fi
command -v apt-get >/dev/null && command -v dpkg >/dev/null || skip "no apt-get/dpkg"

start=$(date +%s)
debs="$cache/debs"
rm -rf "$debs" "$cache/root"
mkdir -p "$debs" "$cache/root"
# What installing would add (a simulation needs no root): blender and its libraries
# less what is installed, and numpy for the glTF importer.
packages=$(apt-get -s install --no-install-recommends blender python3-numpy 2>/dev/null |
           awk '/^Inst /{print $2}') || true
[ -n "$packages" ] || skip "apt-get cannot resolve blender (not a Debian 12 system?)"
# shellcheck disable=SC2086
(cd "$debs" && apt-get download $packages >"$cache/apt-download.log" 2>&1) ||
  { tail -n 5 "$cache/apt-download.log" >&2; skip "apt-get download failed (offline?)"; }
for deb in "$debs"/*.deb; do dpkg -x "$deb" "$cache/root"; done
root="$cache/root"
[ -x "$root/usr/bin/blender" ] || skip "the blender package unpacked no usr/bin/blender"

# Every folder of the unpacked tree that holds a shared library goes on the loader path.
libs=$(find "$root" -name '*.so*' -type f -printf '%h\n' | sort -u | tr '\n' ':')
{
  echo '#!/bin/sh'
  echo "# Runs Blender unpacked by $(basename "$0") into $root."
  printf 'export LD_LIBRARY_PATH=%q${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}\n' "${libs%:}"
  printf 'export PYTHONPATH=%q${PYTHONPATH:+:$PYTHONPATH}\n' "$root/usr/lib/python3/dist-packages"
  # blender-data (scripts, the glTF importer) unpacked here when it was not installed.
  if [ -d "$root/usr/share/blender/scripts" ]; then
    printf 'export BLENDER_SYSTEM_SCRIPTS=%q\n' "$root/usr/share/blender/scripts"
    printf 'export BLENDER_SYSTEM_DATAFILES=%q\n' "$root/usr/share/blender/datafiles"
  fi
  printf 'exec %q "$@"\n' "$root/usr/bin/blender"
} >"$wrapper"
chmod +x "$wrapper"
rm -rf "$debs"
version=$("$wrapper" -b --factory-startup --version 2>/dev/null | head -n 1) ||
  { rm -f "$wrapper"; skip "the unpacked blender does not start: $("$wrapper" -b --version 2>&1 | tail -n 1)"; }
echo "Cycles oracle: $version unpacked into $cache from $(echo "$packages" | wc -w) packages" \
     "in $(( $(date +%s) - start )) s"
