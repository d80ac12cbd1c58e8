#!/usr/bin/env bash
# Makes the compressed-geometry fuzz seeds in tests/data/compressed_seeds with the
# ecosystem's own encoders: small GLBs (1-6 KB) of the shared sample models through
# gltfpack (EXT_meshopt_compression: ATTRIBUTES/TRIANGLES/INDICES streams with the
# OCTAHEDRAL and QUATERNION filters, EXPONENTIAL with -vpf, the KHR_meshopt_compression
# variant; skins, morph targets, animation, vertex colours) and gltf-transform
# (KHR_draco_mesh_compression: positions, normals, UVs, colours, joints and weights).
# Committed, so that the fuzzer (and its sanitizer-build replay) runs without npm.
# Usage: make_fuzz_seeds.sh CACHE_DIR ASSETS_DIR   (the cache of make_corpus.sh)
set -euo pipefail
cache="${1:?usage: make_fuzz_seeds.sh CACHE_DIR ASSETS_DIR}"
assets="${2:?usage: make_fuzz_seeds.sh CACHE_DIR ASSETS_DIR}"
install="$(dirname "$0")/../npm_cache_install.sh"
"$install" gltfpack 1.3.0 "$cache/gltfpack" gltfpack
"$install" @gltf-transform/cli 4.5.1 "$cache/gltf-transform" gltf-transform
gltfpack="$cache/gltfpack/node_modules/.bin/gltfpack"
gltf_transform="$cache/gltf-transform/node_modules/.bin/gltf-transform"
out="$(cd "$(dirname "$0")/../.." && pwd)/tests/data/compressed_seeds"
mkdir -p "$out"
src() { echo "$assets/gltf/$1/glTF/$1.gltf"; }
pack() { # output, model, gltfpack options...
  local name="$1" model="$2"
  shift 2
  "$gltfpack" -i "$(src "$model")" -o "$out/$name" "$@" >/dev/null
}
for model in Box BoxAnimated BoxVertexColors RiggedSimple SimpleMorph; do
  pack "$model.meshopt.glb" "$model" -cc
done
pack Box.meshopt_vpf.glb Box -cc -vpf
pack RiggedSimple.khr_meshopt.glb RiggedSimple -cc -ce khr
for model in Box BoxVertexColors RiggedSimple SimpleMorph; do
  "$gltf_transform" draco "$(src "$model")" "$out/$model.draco.glb" >/dev/null
done
echo "compressed-geometry fuzz seeds written to $out"
