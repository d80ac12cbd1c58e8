#!/bin/sh
# pack.sh BUILD_DIR OUT_DIR: bundle sherpa-cli and sherpa-bench-render with their
# libraries (make_bundle.py), the Khronos validation layer and the glTF assets
# into OUT_DIR/sherpa-device.tar.xz, for the NVIDIA device machine (which has the
# GPU driver but none of our Debian packages). device.sh unpacks and runs it there.
set -eu
build=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
assets=${SHERPA_ASSETS_DIR:-$here/../../../shared/assets}
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
python3 "$here/make_bundle.py" "$stage/sherpa" "$build/cli/sherpa-cli" \
    "$build/bench/sherpa-bench-render"
mkdir -p "$stage/sherpa/layers"
cp /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so "$stage/sherpa/layers/"
sed 's#"library_path": *"[^"]*"#"library_path": "./libVkLayer_khronos_validation.so"#' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json \
    >"$stage/sherpa/layers/VkLayer_khronos_validation.json"
cp -r "$assets/gltf" "$stage/sherpa/gltf"
mkdir -p "$out"
tar -C "$stage" -cf - sherpa | xz -T2 -2 >"$out/sherpa-device.tar.xz"
ls -l "$out/sherpa-device.tar.xz"
