#!/bin/sh
# device.sh TARBALL OUT [rt|rtviews|path]: on the device machine, unpack pack.sh's bundle and run
# every asset through the renderer with the validation layer on (any message
# fails), then the render benchmark at 1280x720. Results land in OUT. With `rt`:
# `sherpa-cli rt --json --validation` (acceleration structures) of every asset and
# the 100k grid instead, one JSON per scene, rt_summary.txt with the totals.
set -u
tarball=$1
out=$2
mode=${3:-render}
work=/tmp/sherpa-device
rm -rf "$work" && mkdir -p "$work" && tar -C "$work" -xJf "$tarball" || exit 1
s=$work/sherpa
# A host C++ runtime at least as new as ours (GCC 12: GLIBCXX_3.4.30) serves both
# us and the GPU driver; ours could be too old for the driver.
host_cxx=/usr/lib/x86_64-linux-gnu/libstdc++.so.6
if [ -f $host_cxx ] && grep -q GLIBCXX_3.4.30 $host_cxx; then rm -f "$s/lib/libstdc++.so.6"; fi
export VK_LAYER_PATH=$s/layers
if [ -z "${VK_DRIVER_FILES:-}" ] && [ -f /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json ] &&
    ! ls /usr/share/vulkan/icd.d/nvidia* /etc/vulkan/icd.d/nvidia* >/dev/null 2>&1; then
    export VK_DRIVER_FILES=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
fi
nvidia-smi -L
fail=0
scenes="builtin:default"
for d in "$s"/gltf/*/; do
    n=$(basename "$d")
    [ -f "$d/glTF/$n.gltf" ] && scenes="$scenes $d/glTF/$n.gltf"
done
if [ "$mode" = path ]; then
    # The path tracer (docs/path_tracer.md): DamagedHelmet lit at 1280x720, samples per
    # second and the estimated error at growing sample counts, validation on.
    for spp in 16 64 256 1024; do
        "$s/run.sh" sherpa-cli render "$s/gltf/DamagedHelmet/glTF/DamagedHelmet.gltf" \
            -o "$out/helmet_path_$spp.png" --renderer rt --view lit --width 1280 --height 720 \
            --spp $spp --validation 2>&1 | tee "$out/helmet_path_$spp.log" | grep -v '^warning'
    done
    exit 0
fi
if [ "$mode" = rtviews ]; then
    sh "$(dirname "$0")/rt_views.sh" "$s" "$out"
    exit 0
fi
if [ "$mode" = rt ]; then
    for scene in $scenes "builtin:grid?n=100000"; do
        name=$(basename "$scene" .gltf | tr ':?=' '___')
        if "$s/run.sh" sherpa-cli rt "$scene" --json --validation >"$out/rt_$name.json" \
            2>"$out/rt_$name.log"; then echo "ok   $name"; else echo "FAIL $name"; cat "$out/rt_$name.log"; fail=1; fi
    done
    python3 - "$out" <<'PY' | tee "$out/rt_summary.txt"
import json, glob, sys
for f in sorted(glob.glob(sys.argv[1] + "/rt_*.json")):
    try: t = json.load(open(f))["totals"]
    except Exception: continue
    print(f.split("/")[-1][3:-5], t["blas"], t["triangles"], t["blas_build_bytes"],
          t["blas_compacted_bytes"], round(t["compaction_ratio"], 3),
          round(t["blas_mtriangles_per_s"], 1), round(t["build_wall_ms"], 1))
PY
    tar -C "$out" -cf "$out/rt.tar" $(cd "$out" && ls rt_*.json rt_*.log) &&
        (cd "$out" && rm -f rt_*.json rt_*.log)
    exit $fail
fi
for scene in $scenes; do
    name=$(basename "$scene" .gltf | tr ':' '_')
    if "$s/run.sh" sherpa-cli render "$scene" -o "$out/$name.png" --width 640 --height 360 \
        --validation --report "$out/$name.json" >"$out/$name.log" 2>&1; then
        echo "ok   $name"
    else
        echo "FAIL $name"; cat "$out/$name.log"; fail=1
    fi
done
# Only a few PNGs come back (8 files at most): keep the reports, pack the images.
(cd "$out" && ls *.png >/dev/null 2>&1 && tar -cf images.tar *.png && rm -f *.png)
python3 - "$out" <<'PY'
import json, glob, sys
rows = {}
for f in sorted(glob.glob(sys.argv[1] + "/*.json")):
    r = json.load(open(f))
    rows[f.split("/")[-1][:-5]] = {"device": r.get("device"), "warnings": r.get("warnings"),
                                   "gpu_ms": r.get("gpu_time_ms", {}).get("frame_median")}
json.dump(rows, open(sys.argv[1] + "/reports.json", "w"), indent=1)
PY
tar -C "$out" -cf "$out/logs.tar" $(cd "$out" && ls *.log *.json | grep -v reports.json) &&
    (cd "$out" && rm -f $(ls *.log *.json | grep -v reports.json))
"$s/run.sh" sherpa-bench-render --frames "${SHERPA_BENCH_FRAMES:-50}" $scenes \
    | tee "$out/bench.txt"
exit $fail
