#!/usr/bin/env bash
# Regenerates the Lab's example charts and tables from the shared sample models:
# sherpa-cli lab per family (docs/lab/README.md). Usage: docs/lab/regenerate.sh [BUILD_DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../../build}"
cli="$build/cli/sherpa-cli"
assets="$here/../../../shared/assets/gltf"
"$cli" lab "$assets/DamagedHelmet/glTF/DamagedHelmet.gltf" --family tangents --csv \
  --chart "$here/tangents_damaged_helmet.svg" > "$here/tangents_damaged_helmet.csv"
"$cli" lab "$assets/DamagedHelmet/glTF/DamagedHelmet.gltf" --family textures --csv \
  --chart "$here/textures_damaged_helmet.svg" > "$here/textures_damaged_helmet.csv"
"$cli" lab "$assets/2CylinderEngine/glTF/2CylinderEngine.gltf" --family culling --csv \
  --chart "$here/culling_2cylinder_engine.svg" > "$here/culling_2cylinder_engine.csv"
"$cli" lab "$assets/2CylinderEngine/glTF/2CylinderEngine.gltf" --family mesh-compression --csv \
  --chart "$here/mesh_compression_2cylinder_engine.svg" > "$here/mesh_compression_2cylinder_engine.csv"
"$cli" lab "$assets/DamagedHelmet/glTF/DamagedHelmet.gltf" --family mesh-compression --csv \
  --chart "$here/mesh_compression_damaged_helmet.svg" > "$here/mesh_compression_damaged_helmet.csv"
# The lighting family (about 2 minutes of lavapipe on a quiet machine: the path tracer's
# 256 + 64 samples at 160x120 are most of it); --json keeps the notes (reference error,
# noise floor, material names), which the CSV has no column for.
"$cli" lab "$assets/DamagedHelmet/glTF/DamagedHelmet.gltf" --family lighting --json \
  --chart "$here/lighting_damaged_helmet.svg" > "$here/lighting_damaged_helmet.json"
