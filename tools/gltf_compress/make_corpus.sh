#!/usr/bin/env bash
# Builds the compressed-geometry test corpus with the ecosystem's own tools, from
# the shared sample models: gltfpack (EXT_meshopt_compression + KHR_mesh_quantization,
# the KHR_meshopt_compression variant, floating-point positions through the
# EXPONENTIAL filter; EXT_mesh_gpu_instancing with -mi) and gltf-transform
# (KHR_draco_mesh_compression, also of skinned, morphed and quantized models;
# EXT_mesh_gpu_instancing). Installs the tools into the cache first (tools/npm_cache_install.sh), skips
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
version="5" # bump when the list below changes
source "$(dirname "$0")/../corpus_lib.sh"
corpus_is_current "$corpus" "$version" compressed-geometry && exit 0
corpus_start "$corpus" "$version" "file source-model codec: one compressed file per line"
pack() { # output, model, codec, gltfpack options...
  local out="$1" model="$2" codec="$3"; shift 3
  run_logged "$corpus/$out.log" "gltfpack on $out" \
    "$gltfpack" -i "$assets/gltf/$model/glTF/$model.gltf" -o "$corpus/$out" "$@"
  corpus_add "$corpus" "$out $model $codec"
}
for model in Duck DamagedHelmet BoxTextured 2CylinderEngine; do
  pack "$model.meshopt.glb" "$model" EXT_meshopt_compression -cc
done
pack Duck.meshopt_vpf.glb Duck EXT_meshopt_compression -cc -vpf
pack Duck.meshopt.gltf Duck EXT_meshopt_compression -cc # .gltf + .bin: the broken variants start here
pack Duck.khr_meshopt.glb Duck KHR_meshopt_compression -cc -ce khr
# -cf: an uncompressed fallback buffer with the file's bytes (the importer shows those
# where a stream does not decode).
pack Duck.meshopt_fallback.gltf Duck EXT_meshopt_compression -c -cf
# Animation data: gltfpack stores rotations through the QUATERNION filter.
pack BoxAnimated.meshopt.glb BoxAnimated EXT_meshopt_compression -cc
draco() { # output, model
  local out="$1" model="$2"
  run_logged "$corpus/$out.log" "gltf-transform draco on $out" \
    "$gltf_transform" draco "$assets/gltf/$model/glTF/$model.gltf" "$corpus/$out"
  corpus_add "$corpus" "$out $model KHR_draco_mesh_compression"
}
for model in Duck DamagedHelmet BoxTextured 2CylinderEngine; do
  draco "$model.draco.glb" "$model"
done
draco Duck.draco.gltf Duck # .gltf + .bin: the broken variants start here
# Every attribute kind through Draco: skins (JOINTS_0 as unsigned short, WEIGHTS_0),
# morph targets (kept uncompressed beside the stream), and gltf-transform quantize's
# normalized integers (COLOR_0 unsigned byte, UVs unsigned short, positions and
# normals short) before Draco.
for model in RiggedSimple VC SimpleMorph AnimatedMorphSphere; do
  draco "$model.draco.glb" "$model"
done
run_logged "$corpus/BoxVertexColors.quantized.glb.log" "gltf-transform quantize on BoxVertexColors" \
  "$gltf_transform" quantize "$assets/gltf/BoxVertexColors/glTF/BoxVertexColors.gltf" \
  "$corpus/BoxVertexColors.quantized.glb"
run_logged "$corpus/BoxVertexColors.quantized.draco.glb.log" "gltf-transform draco on BoxVertexColors.quantized" \
  "$gltf_transform" draco "$corpus/BoxVertexColors.quantized.glb" "$corpus/BoxVertexColors.quantized.draco.glb"
corpus_add "$corpus" "BoxVertexColors.quantized.draco.glb BoxVertexColors KHR_draco_mesh_compression"
# EXT_mesh_gpu_instancing: gltfpack -mi (marked required; quantized rotations) and
# gltf-transform instance (float rows).
pack 2CylinderEngine.instanced.glb 2CylinderEngine EXT_mesh_gpu_instancing -mi
run_logged "$corpus/2CylinderEngine.gt_instance.glb.log" "gltf-transform instance on 2CylinderEngine" \
  "$gltf_transform" instance "$assets/gltf/2CylinderEngine/glTF/2CylinderEngine.gltf" \
  "$corpus/2CylinderEngine.gt_instance.glb"
corpus_add "$corpus" "2CylinderEngine.gt_instance.glb 2CylinderEngine EXT_mesh_gpu_instancing"
corpus_finish "$corpus" "$version" compressed-geometry
