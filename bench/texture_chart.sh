#!/usr/bin/env bash
# Regenerates docs/textures/: the speed/quality sweep CSV and its charts.
#   bench/texture_chart.sh [BUILD_DIR] [--plot-only]   (default: build; --plot-only
#   redraws the charts from the existing docs/textures/sweep.csv)
# Runs sherpa-texture-sweep single-threaded over the corpus (13 colour maps, the
# alpha maps, 13 normal maps), then draws ms/MPix against PSNR (BC7) and against
# mean normal-angle error (BC5) with the reference anchor points as markers.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
out=docs/textures
if [ "${2:-}" != "--plot-only" ]; then
  "$build/bench/sherpa-texture-sweep" --textures 13 --threads 1 --csv "$out/sweep.csv" | tee "$out/sweep.md"
fi
command -v gnuplot >/dev/null || { echo "gnuplot missing (apt-get install gnuplot-nox)" >&2; exit 1; }
# One data file per series: gnuplot's linespoints break at rows filtered to NaN.
series=$(mktemp -d)
trap 'rm -rf "$series"' EXIT
for kind in bc7-rgb bc7-rgba bc5; do grep "^$kind," "$out/sweep.csv" >"$series/$kind.csv"; done
grep -v '^#' "$out/anchors.csv" | grep '^bc7,' >"$series/anchors-bc7.csv"
grep -v '^#' "$out/anchors.csv" | grep '^bc5,' >"$series/anchors-bc5.csv"
draw() { # $1: gnuplot terminal, $2: file extension
gnuplot <<PLOT
set datafile separator ','
set terminal $1 size 900,560 font 'sans,11'
set key top left
set grid
set logscale x
set xlabel 'encode time, ms per megapixel (one core, log scale)'

set output 'docs/textures/bc7_speed_quality.$2'
set title 'BC7: speed against quality (13 colour maps, RGB; alpha maps, RGBA)'
set ylabel 'PSNR, dB'
plot '$series/bc7-rgb.csv' using 5:7 with linespoints pt 7 lw 2 title 'Sherpa BC7 levels 0-4, pooled RGB PSNR', \
     '$series/bc7-rgb.csv' using 5:6 with linespoints pt 6 dt 2 title 'Sherpa BC7, mean of per-texture RGB PSNR', \
     '$series/bc7-rgba.csv' using 5:7 with linespoints pt 9 title 'Sherpa BC7 on alpha maps, pooled RGBA PSNR', \
     '$series/anchors-bc7.csv' using 3:4:2 with labels point pt 2 ps 1.5 offset 0,-0.9 font ',10' title 'anchors'

set output 'docs/textures/bc5_speed_quality.$2'
set title 'BC5 normal maps: speed against mean normal-angle error (13 normal maps)'
set ylabel 'mean angle error, degrees (lower is better)'
set yrange [0:1.7]
plot '$series/bc5.csv' using 5:8 with linespoints pt 7 lw 2 title 'Sherpa BC5 levels 0-1 (reference Z rebuilt from source RG)', \
     '$series/bc5.csv' using 5:9 with linespoints pt 6 dt 2 title 'Sherpa BC5 levels 0-1 (reference: normalised source RGB)', \
     '$series/anchors-bc5.csv' using 3:5:2 with labels point pt 2 ps 1.5 offset 0,0.9 font ',10' title 'anchors'
PLOT
}
draw svg svg
draw pngcairo png
echo "wrote $out/sweep.csv, $out/sweep.md and the charts $out/bc{7,5}_speed_quality.{svg,png}"
