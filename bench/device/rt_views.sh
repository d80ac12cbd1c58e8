#!/bin/sh
# rt_views.sh SHERPA_DIR OUT: the ray tracer on the device (issue #17), called by
# device.sh's `rtviews` mode. Every asset and RT view at 320x240 under the validation
# layer (any message fails), posed frames, repeated runs of VC's normal view (a crash
# seen once), frame costs at 1280x720 (raster vs rays, shadows, AO, comparisons) and
# the Lab's shadows family on four real scenes (JSON + SVG chart).
set -u
s=$1
out=$2
cli="$s/run.sh sherpa-cli"
views="normal tangent uv0 base-color roughness shadow ao shadow-error"
jobs=$out/jobs.txt
: >"$jobs"
for d in "$s"/gltf/*/; do
    n=$(basename "$d")
    [ -f "$d/glTF/$n.gltf" ] || continue
    for v in $views; do echo "$n $v $d/glTF/$n.gltf" >>"$jobs"; done
done
mkdir -p "$out/views"
# One process per (scene, view), eight at a time: the validation layer is CPU-bound.
xargs -P 8 -L 1 sh -c '
    if '"$cli"' render "$2" -o "'"$out"'/views/$0_$1.png" --renderer rt --view $1 \
        --width 320 --height 240 --validation >"'"$out"'/views/$0_$1.log" 2>&1
    then echo "ok   $0 $1"; else echo "FAIL $0 $1 (exit $?)"; fi' <"$jobs" |
    sort >"$out/views.txt"
echo "views: $(grep -c '^ok' "$out/views.txt") ok, $(grep -c '^FAIL' "$out/views.txt") failed"
grep '^FAIL' "$out/views.txt"
for m in RiggedSimple SimpleMorph AnimatedMorphSphere BoxAnimated; do
    for t in 0.3 1.1; do
        if $cli render "$s/gltf/$m/glTF/$m.gltf" -o "$out/views/posed_${m}_$t.png" --renderer rt \
            --view normal --animation 0 --time $t --width 320 --height 240 --validation \
            >"$out/views/posed_${m}_$t.log" 2>&1; then echo "ok   posed $m $t"; else echo "FAIL posed $m $t"; fi
    done
done
vc=$s/gltf/VC/glTF/VC.gltf
crashes=0
for i in 1 2 3 4 5 6 7 8 9 10; do
    $cli render "$vc" -o "$out/vc.png" --renderer rt --view normal --width 320 --height 240 \
        --validation >/dev/null 2>&1 || crashes=$((crashes + 1))
done
echo "VC rt normal: $crashes of 10 runs failed"
# Frame costs, median GPU ms of 30 frames at 1280x720.
cost() { # name, then render arguments
    name=$1
    shift
    $cli render "$@" -o "$out/cost.png" --width 1280 --height 720 --frames 30 \
        --report "$out/cost_$name.json" >"$out/cost_$name.log" 2>&1
    python3 -c 'import json,sys; print(sys.argv[2], json.load(open(sys.argv[1]))["gpu_time_ms"]["frame_median"])' \
        "$out/cost_$name.json" "$name" 2>/dev/null || echo "$name FAILED"
}
for n in DamagedHelmet 2CylinderEngine Duck VC; do
    f=$s/gltf/$n/glTF/$n.gltf
    cost "${n}_raster_normal" "$f" --view normal --no-shadows
    cost "${n}_rt_normal" "$f" --renderer rt --view normal --no-shadows
    cost "${n}_raster_shadow" "$f" --view shadow
    cost "${n}_rt_shadow_hard" "$f" --renderer rt --view shadow
    cost "${n}_rt_shadow_soft16" "$f" --renderer rt --view shadow --shadow-rays 16 --sun-angular-radius 0.05
    cost "${n}_rt_ao16" "$f" --renderer rt --view ao --ao-rays 16
done | tee "$out/costs.txt"
for n in DamagedHelmet Duck; do
    $cli render "$s/gltf/$n/glTF/$n.gltf" -o "$out/compare_$n.png" --width 1280 --height 720 \
        --view normal --no-shadows --compare difference --compare-renderer rt --frames 10 --json \
        >"$out/compare_$n.json" 2>"$out/compare_$n.log" || echo "FAIL compare $n"
done
for n in Duck DamagedHelmet 2CylinderEngine VC; do
    $cli lab "$s/gltf/$n/glTF/$n.gltf" --family shadows --json --chart "$out/shadows_$n.svg" \
        >"$out/shadows_$n.json" 2>"$out/shadows_$n.log" || echo "FAIL lab shadows $n"
done
(cd "$out" && tar -cf views.tar views && rm -rf views jobs.txt cost.png vc.png)
