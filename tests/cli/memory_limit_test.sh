#!/bin/sh
# Oversized input under a 2 GB address-space limit (ulimit -v 2000000): images whose
# headers declare 30000x30000, 65500x65500 and 16384x16384 texels (a 68-byte PNG, a
# 112-byte JPEG, a 42-byte WebP, an 8 KB UASTC KTX2 whose Zstandard level inflates to
# 256 MiB), a meshopt view whose fallback buffer declares 1.8 GB, and Draco streams of
# 136-138 bytes whose headers declare 2^28 triangles (for 36 indices) or 20M (for as
# many indices) (tests/data/make_oversized.py). Every command that decodes them must finish
# normally (no signal, no std::bad_alloc abort, no "out of memory"), name each bomb
# with its declared size, and still show what can be shown.
# usage: memory_limit_test.sh SHERPA_CLI DATA_DIR WORK_DIR
set -u
cli=$1 data=$2 work=$3
rm -rf "$work" && mkdir -p "$work" || exit 2
ulimit -v 2000000 || exit 2
bombs="$data/image_bombs.gltf"
failures=0

# run NAME EXPECTED_EXIT COMMAND...: runs sherpa-cli, keeps its output in $work/NAME.out.
run() {
    name=$1 expected=$2
    shift 2
    "$cli" "$@" >"$work/$name.out" 2>&1
    rc=$?
    if [ "$rc" -ne "$expected" ]; then
        echo "FAIL $name: exit $rc, expected $expected ($*)"
        sed 's/^/    /' "$work/$name.out" | head -20
        failures=$((failures + 1))
    fi
    if grep -qi "out of memory\|bad_alloc" "$work/$name.out"; then
        echo "FAIL $name: reports running out of memory"
        failures=$((failures + 1))
    fi
}

# expect NAME TEXT: the output of run NAME contains TEXT.
expect() {
    if ! grep -qF -- "$2" "$work/$1.out"; then
        echo "FAIL $1: output lacks \"$2\""
        failures=$((failures + 1))
    fi
}

# Each bomb's declared size ...
expect_sizes() {
    expect "$1" "declares 30000x30000 texels"
    expect "$1" "declares 65500x65500 texels"
    expect "$1" "declares 16384x16384 texels"
}
# ... and its file.
expect_bombs() {
    expect_sizes "$1"
    expect "$1" "bomb_30000.png"
    expect "$1" "bomb_65500.jpg"
    expect "$1" "bomb_16384.webp"
    expect "$1" "bomb_uastc_zstd.ktx2"
}

run info 0 info "$bombs"
expect_bombs info
run info_json 0 info "$bombs" --json
expect_bombs info_json
run textures 0 textures "$bombs" --json --cache-dir "$work/cache"
expect_bombs textures
expect textures '"state": "undecodable"'
run export 1 textures "$bombs" --export-source "$work/export"
expect_bombs export
[ -s "$work/export/good_2x2.png" ] || { echo "FAIL export: good_2x2.png not written"; failures=$((failures + 1)); }
run budget 0 budget "$bombs" --json
expect_sizes budget # budget names images by index ("image 0 not measured: ...")
run compare 0 compare "$bombs" "$bombs" --json
expect_bombs compare
run lab 0 lab "$bombs" --family textures --json
expect_bombs lab
run render 0 render "$bombs" -o "$work/render.png" --width 32 --height 32 --cache-dir "$work/cache"
expect_bombs render
[ -s "$work/render.png" ] || { echo "FAIL render: no image written"; failures=$((failures + 1)); }

# 1.84 GB of RSS before: now the 36 bytes the stream decodes.
run meshopt 0 info "$data/meshopt_fallback_1800mb.gltf" --json
expect meshopt '"vertices": 3'

# Draco 1.5.5 sized its corner table by these counts (6 GB for 2^28 triangles) and
# the load failed "out of memory while importing": now each primitive is skipped before
# Draco sees it, naming the primitive and the count, and the rest of the file loads.
run draco_faces 0 info "$data/draco_faces_268m.gltf"
expect draco_faces "KHR_draco_mesh_compression: the Draco stream (bufferViews[0], 138 bytes) declares 268435456 triangles"
run draco_limit 0 info "$data/draco_faces_20m.gltf" --json
expect draco_limit "Sherpa decodes at most 16777216 triangles per Draco primitive (primitive skipped)"

if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s); outputs in $work"
    exit 1
fi
echo "all commands finished under ulimit -v 2000000"
