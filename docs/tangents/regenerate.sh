#!/usr/bin/env bash
# Regenerates everything in docs/tangents: the CSVs (from sherpa-tangent-report, built
# from this checkout) and the charts (gnuplot, SVG and PNG).
# Usage: docs/tangents/regenerate.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
command -v gnuplot >/dev/null || { echo "regenerate: gnuplot missing (run .ci/setup)" >&2; exit 1; }
cmake --build "$build" --target sherpa-tangent-report -- -j2
cache="$(sed -n 's/^SHERPA_ORACLE_CACHE:PATH=//p' "$build/CMakeCache.txt")"
"$root/tools/tangents/install_oracle.sh" "$cache"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$work" && "$build/bench/sherpa-tangent-report" "$here" --repeat 3)

# Chart inputs: one file per method (methods chart), one cell per case and method
# (sweep table), with the cell's colour: 0 fine, 1 fallbacks or unguarded NaN, 2 wrong.
for m in mikktspace mikktspace-welded lengyel reference-wasm; do
  awk -F, -v m="$m" 'NR > 1 && $2 == m' "$here/methods.csv" > "$work/$m.csv"
done
awk -F, 'NR == 1 { next }
  { if (!($1 in row)) { row[$1] = n++; names[row[$1]] = $1 }
    col = ($2 == "mikktspace") ? 0 : ($2 == "mikktspace-welded") ? 1 : 2
    # columns from the end: nonfinite_before_guard, nan_in_output, max_error_deg, flips
    unguarded = $(NF-3); nan_out = $(NF-2); err = $(NF-1); flips = $NF
    status = (err > 1 || flips > 0 || nan_out > 0) ? 2 : (($4 > 0 || unguarded > 0) ? 1 : 0)
    printf "%d %d %d \"fallbacks %d, unguarded NaN %d\\nmax error %.2g deg\\nhandedness flips %d\\nNaN out %d\"\n", col, row[$1], status, $4, unguarded, err, flips, nan_out }
  END { for (i = 0; i < n; ++i) printf "%d %s\n", i, names[i] > "'"$work"'/rows.txt" }' \
  "$here/sweep.csv" > "$work/cells.txt"

for term in svg png; do
  gnuplot -e "work='$work'; out='$here'; term='$term'" "$here/charts.gp"
done
echo "regenerated $here"
