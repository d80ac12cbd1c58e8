#!/bin/sh
# Regenerates culling.csv and culling.png from a fresh benchmark run.
# Usage (from the repository root, after .ci/build): docs/culling/regenerate.sh
set -eu
here=$(dirname "$0")
build/bench/sherpa-bench-cull --csv "$here/culling.csv" | tee "$here/culling.txt"
gnuplot -e "csv='$here/culling.csv'; out='$here/culling.png'" "$here/culling.gp"
echo "wrote $here/culling.csv, $here/culling.txt, $here/culling.png"
