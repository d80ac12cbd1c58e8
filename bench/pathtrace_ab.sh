#!/usr/bin/env bash
# Same-run A/B of two builds' path tracers: N interleaved pairs of
# sherpa-bench-pathtrace (A, then B), each pair's "path traced" CPU and GPU ms per
# sample, B/A for the CPU column (the steadier one on a shared machine), and the median
# of those ratios. Extra arguments go to the benchmark.
#   bench/pathtrace_ab.sh BUILD_A BUILD_B N [--rounds 2 --frames 3 ...]
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 BUILD_A BUILD_B N [benchmark arguments]" >&2
  exit 2
fi
a_dir=$1 b_dir=$2 pairs=$3
shift 3
sample() { "$1/bench/sherpa-bench-pathtrace" "${@:2}" 2>&1 | awk '/^path traced/{print $3, $4}'; }
ratios=()
printf '%-4s %12s %12s %12s %12s %8s %6s\n' pair "A GPU ms" "A CPU ms" "B GPU ms" "B CPU ms" "B/A CPU" load
for i in $(seq 1 "$pairs"); do
  read -r ag ac < <(sample "$a_dir" "$@")
  read -r bg bc < <(sample "$b_dir" "$@")
  r=$(awk -v a="$ac" -v b="$bc" 'BEGIN{printf "%.3f", b/a}')
  ratios+=("$r")
  printf '%-4s %12s %12s %12s %12s %8s %6s\n' "$i" "$ag" "$ac" "$bg" "$bc" "$r" "$(cut -d' ' -f1 /proc/loadavg)"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{v[NR]=$1} END{m=(NR%2)?v[(NR+1)/2]:(v[NR/2]+v[NR/2+1])/2; printf "median B/A CPU per sample: %.3f over %d pairs\n", m, NR}'
