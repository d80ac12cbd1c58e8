# Charts for docs/tangents; run by regenerate.sh with work, out and term set.
if (term eq 'svg') { set terminal svg size 1100,600 dynamic font 'sans,11' } else { set terminal pngcairo size 1100,600 font 'sans,10' }
set datafile separator ','

# --- time against error, one point per method per model -----------------------------
set output out.'/methods.'.term
set multiplot layout 1,2 title 'Tangent methods on the sample models and a 250k-triangle torus (CPU time on one core)'
set logscale xy
set grid
set key below horizontal font ',9'
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 'ms per million triangles (log)'
clampfloor(x) = (x > 1e-7) ? x : 1e-7
set ylabel 'p99 angle error against exact MikkTSpace, degrees (log; 1e-7 = none)'
set yrange [5e-8:500]
plot work.'/mikktspace.csv' using 4:(clampfloor($10)) with points pt 7 ps 1.2 lc rgb '#1b9e77' title 'mikktspace (exact, split)', \
     work.'/mikktspace-welded.csv' using 4:(clampfloor($10)) with points pt 5 ps 1.2 lc rgb '#d95f02' title 'mikktspace-welded (last write)', \
     work.'/lengyel.csv' using 4:(clampfloor($10)) with points pt 9 ps 1.4 lc rgb '#7570b3' title 'lengyel (per vertex sum)', \
     work.'/reference-wasm.csv' using 4:(clampfloor($10)) with points pt 3 ps 1.2 lc rgb '#666666' title 'reference (wasm oracle)'
set ylabel 'p99 angle error against authored tangents, degrees (log)'
plot work.'/mikktspace.csv' using 4:(strlen(strcol(6)) ? clampfloor($6) : NaN) with points pt 7 ps 1.2 lc rgb '#1b9e77' title 'mikktspace (exact, split)', \
     work.'/mikktspace-welded.csv' using 4:(strlen(strcol(6)) ? clampfloor($6) : NaN) with points pt 5 ps 1.2 lc rgb '#d95f02' title 'mikktspace-welded', \
     work.'/lengyel.csv' using 4:(strlen(strcol(6)) ? clampfloor($6) : NaN) with points pt 9 ps 1.4 lc rgb '#7570b3' title 'lengyel', \
     work.'/reference-wasm.csv' using 4:(strlen(strcol(6)) ? clampfloor($6) : NaN) with points pt 3 ps 1.2 lc rgb '#666666' title 'reference (wasm oracle)'
unset multiplot

# --- failure table of the stability sweep --------------------------------------------
if (term eq 'svg') { set terminal svg size 1100,1300 dynamic font 'sans,10' } else { set terminal pngcairo size 1100,1300 font 'sans,9' }
set output out.'/sweep.'.term
reset
set datafile separator whitespace
set title 'Stability sweep: generated meshes that break tangent methods (green: exact; amber: fallbacks or NaN caught by the guard; red: wrong tangents)'
rows = system('wc -l < '.work.'/rows.txt') + 0
set xrange [-0.5:2.5]
set yrange [rows - 0.5:-0.5]
set xtics ('mikktspace' 0, 'mikktspace-welded' 1, 'lengyel' 2) scale 0
set ytics scale 0
set ytics () 
do for [i=0:rows-1] { set ytics add (system('sed -n '.(i+1).'p '.work.'/rows.txt | cut -d" " -f2') i) }
unset key
set border 0
set palette defined (0 '#c7e9c0', 1 '#fdd49e', 2 '#fc9272')
set cbrange [0:2]
unset colorbox
plot work.'/cells.txt' using 1:2:(0.49):(0.47):3 with boxxyerror fs solid 1.0 noborder lc palette, \
     '' using 1:2:4 with labels font ',8'
