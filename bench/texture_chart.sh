#!/usr/bin/env bash
# Regenerates docs/textures/: the speed/quality sweep CSV and its charts.
#   bench/texture_chart.sh [BUILD_DIR]      (default: build)
# Runs sherpa-texture-sweep single-threaded over the corpus (13 colour maps, the
# alpha maps, 13 normal maps), then draws ms/MPix against PSNR (BC7) and against
# mean normal-angle error (BC5) with the issue's anchor points as markers.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
out=docs/textures
"$build/bench/sherpa-texture-sweep" --textures 13 --threads 1 --csv "$out/sweep.csv" | tee "$out/sweep.md"
command -v gnuplot >/dev/null || { echo "gnuplot missing (apt-get install gnuplot-nox)" >&2; exit 1; }
gnuplot <<'PLOT'
set datafile separator ','
set terminal svg size 900,560 dynamic font 'sans,12'
set key bottom right
set grid
set logscale x
set xlabel 'encode time, ms per megapixel (one core, log scale)'

set output 'docs/textures/bc7_speed_quality.svg'
set title 'BC7: speed against quality (13 colour maps, RGB; alpha maps, RGBA)'
set ylabel 'PSNR, dB'
plot 'docs/textures/sweep.csv' using ($5):(strcol(1) eq 'bc7-rgb' ? $7 : NaN) with linespoints pt 7 lw 2 title 'Sherpa BC7, pooled RGB PSNR (levels 0-4)', \
     '' using ($5):(strcol(1) eq 'bc7-rgb' ? $6 : NaN) with linespoints pt 6 dt 2 title 'Sherpa BC7, mean per-texture RGB PSNR', \
     '' using ($5):(strcol(1) eq 'bc7-rgba' ? $7 : NaN) with linespoints pt 9 title 'Sherpa BC7 on alpha maps, pooled RGBA PSNR', \
     'docs/textures/anchors.csv' using ($3):(strcol(1) eq 'bc7' ? $4 : NaN):2 with labels point pt 2 ps 1.5 offset 1,-0.8 font ',10' title 'anchors (issue #5)'

set output 'docs/textures/bc5_speed_quality.svg'
set title 'BC5 normal maps: speed against mean normal-angle error (13 normal maps)'
set ylabel 'mean angle error, degrees (lower is better)'
set key top right
plot 'docs/textures/sweep.csv' using ($5):(strcol(1) eq 'bc5' ? $8 : NaN) with linespoints pt 7 lw 2 title 'Sherpa BC5 (levels 0-1)', \
     'docs/textures/anchors.csv' using ($3):(strcol(1) eq 'bc5' ? $5 : NaN):2 with labels point pt 2 ps 1.5 offset 1,0.8 font ',10' title 'anchors (issue #5)'
PLOT
echo "wrote $out/sweep.csv, $out/sweep.md, $out/bc7_speed_quality.svg, $out/bc5_speed_quality.svg"
