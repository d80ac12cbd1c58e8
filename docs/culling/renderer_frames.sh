#!/bin/sh
# Frame times of the renderer with each culling path (none, cpu, gpu) on the 10k and
# 100k grids at 1280x720, from the auto camera (the whole grid in view) and from a
# camera inside the grid, plus triangles per pass (camera, each shadow cascade).
# Runs are interleaved and repeated; the summary gives medians over runs of each
# report's frame median, and the per-run ratio to `none` (same minute, same load).
# Usage (from the repository root, after .ci/build): docs/culling/renderer_frames.sh [RUNS]
set -eu
runs=${1:-3}
out=$(mktemp -d)
close="eye=0,6,20:target=0,0,0"
for rep in $(seq "$runs"); do
  for n in 10000 100000; do
    for path in none cpu gpu; do
      build/cli/sherpa-cli render "builtin:grid?n=$n" -o "$out/g.png" --width 1280 --height 720 \
        --frames 10 --cull $path --report "$out/grid_${n}_${path}_$rep.json" > /dev/null
      build/cli/sherpa-cli render "builtin:grid?n=$n" -o "$out/g.png" --width 1280 --height 720 \
        --frames 10 --cull $path --camera $close --report "$out/close_${n}_${path}_$rep.json" > /dev/null
    done
  done
done
python3 - "$out" <<'PY'
import glob, json, statistics as st, sys
d = sys.argv[1]
for cam in ["grid", "close"]:
    for n in [10000, 100000]:
        base = {}
        for path in ["none", "cpu", "gpu"]:
            runs = {f.rsplit("_", 1)[1]: json.load(open(f))
                    for f in glob.glob(f"{d}/{cam}_{n}_{path}_*.json")}
            ms = {r: j["cpu_frame_ms_median"] for r, j in runs.items()}
            first = st.median(j["gpu_time_ms"]["first_frame"] for j in runs.values())
            if path == "none":
                base = ms
            ratio = [ms[r] / base[r] for r in ms if r in base]
            last = runs[max(runs)]
            c = last["culling"]
            print(f"{'auto ' if cam == 'grid' else 'close'} n={n:>6} {path}: frame {st.median(ms.values()):7.1f} ms "
                  f"({1000 / st.median(ms.values()):5.2f} fps), x none {st.median(ratio):4.2f}, "
                  f"first frame (draws the cascades) {first:7.1f} ms; "
                  f"camera {c[0]['visible']}/{c[0]['total']} visible, {c[0]['triangles']} tris; "
                  f"shadow tris {sum(p['triangles'] for p in c[1:])} {[p['triangles'] for p in c[1:]]}; "
                  f"cull cpu {c[0]['cpu_ms_median']:.3f} ms gpu {c[0]['gpu_ms_median']:.3f} ms (camera)")
PY
rm -r "$out"
