#!/usr/bin/env bash
# Makes the image fuzz seeds in tests/data/image_seeds with oiiotool (OpenImageIO,
# a Debian package): tiny PNG, JPEG and WebP files (a few hundred bytes) of each kind
# the decoders branch on: RGBA, grey and 16-bit PNG; baseline RGB, grey and
# progressive JPEG; lossy (with alpha) and lossless WebP. Usage:
#   make_fuzz_seeds.sh ASSETS_DIR
set -euo pipefail
assets="${1:?usage: make_fuzz_seeds.sh ASSETS_DIR}"
out="$(cd "$(dirname "$0")/../.." && pwd)/tests/data/image_seeds"
mkdir -p "$out"
cd "$out"
oiiotool "$assets/gltf/VC/glTF/prop128.png" --resize 13x9 -o rgba13.png
oiiotool "$assets/gltf/BoxTexturedNonPowerOfTwo/glTF/CesiumLogoFlat.png" --resize 20x12 \
  --ch R,G,B -o rgb20.jpg
oiiotool rgba13.png --ch R -o grey13.png
oiiotool rgba13.png -d uint16 -o rgba13_16.png
oiiotool rgb20.jpg --ch R -o grey20.jpg
oiiotool rgb20.jpg --attrib jpeg:progressive 1 -o rgb20_progressive.jpg
oiiotool rgba13.png -o rgba13.webp
oiiotool rgb20.jpg --attrib compression lossless -o rgb20_lossless.webp
echo "image fuzz seeds written to $out"
