#!/usr/bin/env bash
# Builds the compressed-geometry test corpus with the ecosystem's own tools, from
# the shared sample models: gltfpack (EXT_meshopt_compression + KHR_mesh_quantization,
# the KHR_meshopt_compression variant, floating-point positions through the
# EXPONENTIAL filter) and gltf-transform (KHR_draco_mesh_compression). Installs the tools into the cache first (tools/npm_cache_install.sh), skips
# work already done. Usage: make_corpus.sh CACHE_DIR ASSETS_DIR
set -euo pipefail
cache="${1:?usage: make_corpus.sh CACHE_DIR ASSETS_DIR}"
assets="${2:?usage: make_corpus.sh CACHE_DIR ASSETS_DIR}"
# One cache folder per tool: a --no-save npm install prunes packages it was not given.
install="$(dirname "$0")/../npm_cache_install.sh"
"$install" gltfpack 1.3.0 "$cache/gltfpack" gltfpack
"$install" @gltf-transform/cli 4.5.1 "$cache/gltf-transform" gltf-transform
gltfpack="$cache/gltfpack/node_modules/.bin/gltfpack"
gltf_transform="$cache/gltf-transform/node_modules/.bin/gltf-transform"
corpus="$cache/corpus"
stamp="$corpus/manifest.txt"
version="2" # bump when the list below changes
if [ -f "$stamp" ] && head -n1 "$stamp" | grep -qx "# corpus v$version"; then
  echo "compressed-geometry corpus v$version cached in $corpus"; exit 0
fi
rm -rf "$corpus"; mkdir -p "$corpus"
{
  echo "# corpus v$version"
  echo "# file source-model codec: one compressed file per line"
} >"$stamp.tmp"
pack() { # output, model, codec, gltfpack options...
  local out="$1" model="$2" codec="$3"; shift 3
  "$gltfpack" -i "$assets/gltf/$model/glTF/$model.gltf" -o "$corpus/$out" "$@" \
    >"$corpus/$out.log" 2>&1 || { echo "gltfpack failed on $out:"; tail -n 5 "$corpus/$out.log"; exit 1; } >&2
  echo "$out $model $codec" >>"$stamp.tmp"
}
for model in Duck DamagedHelmet BoxTextured 2CylinderEngine; do
  pack "$model.meshopt.glb" "$model" EXT_meshopt_compression -cc
done
pack Duck.meshopt_vpf.glb Duck EXT_meshopt_compression -cc -vpf
pack Duck.meshopt.gltf Duck EXT_meshopt_compression -cc # .gltf + .bin: the broken variants start here
pack Duck.khr_meshopt.glb Duck KHR_meshopt_compression -cc -ce khr
draco() { # output, model
  local out="$1" model="$2"
  "$gltf_transform" draco "$assets/gltf/$model/glTF/$model.gltf" "$corpus/$out" \
    >"$corpus/$out.log" 2>&1 || { echo "gltf-transform draco failed on $out:"; tail -n 5 "$corpus/$out.log"; exit 1; } >&2
  echo "$out $model KHR_draco_mesh_compression" >>"$stamp.tmp"
}
for model in Duck DamagedHelmet BoxTextured 2CylinderEngine; do
  draco "$model.draco.glb" "$model"
done
draco Duck.draco.gltf Duck # .gltf + .bin: the broken variants start here
mv "$stamp.tmp" "$stamp"
echo "compressed-geometry corpus v$version written to $corpus"
