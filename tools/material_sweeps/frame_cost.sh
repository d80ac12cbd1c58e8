#!/usr/bin/env bash
# Same-run comparison of two sherpa-cli builds on one file (e.g. main's and a branch's):
# alternating renders at 1280x720, printing each run's median GPU frame and opaque-pass
# times and its GPU bytes. Compare the medians of the two columns, as ratios, within one
# run only (shared machines are noisy).
# Usage: frame_cost.sh CLI_A CLI_B MODEL [ROUNDS] [extra render options...]
set -euo pipefail
a="${1:?usage: frame_cost.sh CLI_A CLI_B MODEL [ROUNDS] [options]}"
b="${2:?}"
model="${3:?}"
rounds="${4:-3}"
shift $(( $# < 4 ? $# : 4 ))
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
for ((i = 0; i < rounds; ++i)); do
  for side in A B; do
    cli="$a"; [ "$side" = B ] && cli="$b"
    "$cli" render "$model" -o "$out/frame.png" --width 1280 --height 720 --frames 8 \
      --report "$out/report.json" --no-cache "$@" >/dev/null 2>&1
    python3 - "$side" "$out/report.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[2]))
g, m = j["gpu_time_ms"], j["gpu_memory_bytes"]
print(sys.argv[1], "frame_gpu_ms %.1f" % g["frame_median"],
      "opaque_gpu_ms %.1f" % g["passes_median"]["opaque"],
      "materials", m["materials"], "material_extensions", m.get("material_extensions", "-"),
      "total", m["total"])
PY
  done
done
