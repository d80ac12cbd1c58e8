# Speed against accuracy for CPU frustum culling on builtin:grid: ns per object
# (log scale) for each method and size, labelled with its false positives against
# the exact test. "read floor" is the memory-read floor measured in the same run;
# "pass" is the whole camera pass (cull + draw-group build); "all in view" is the
# fastest p-vertex path with every box in view (no SIMD block ends early).
set terminal pngcairo size 1300,640 font ",11"
set bmargin 4
set output out
set datafile separator ","
set logscale y
set ylabel "ns per object (one core, median of 21)"
set title "Sherpa culling on builtin:grid: ns/object, labelled with false positives vs the exact test"
set key top left
set grid ytics
set xrange [-0.6:8.6]
set xtics ("read floor" 0, "sphere" 1, "p-vertex\nscalar" 2, "p-vertex\nAVX2" 3, "p-vertex\nAVX-512" 4, "exact\n(SAT)" 5, "pass:\ncull+groups" 6, "GPU p-vertex\n(lavapipe)" 7, "fastest,\nall in view" 8)
idx(s) = s eq "read floor" ? 0 : s eq "sphere" ? 1 : s eq "pvertex scalar" ? 2 : s eq "pvertex avx2" ? 3 : \
         s eq "pvertex avx512" ? 4 : s eq "exact" ? 5 : s eq "pass (cull+groups)" ? 6 : s eq "gpu pvertex" ? 7 : s eq "pvertex avx512 all" || s eq "pvertex avx2 all" || s eq "pvertex scalar all" ? 8 : NaN
sizes = "10000 100000 1000000"
off(i) = (i - 2) * 0.22
plot for [i=1:3] csv using (stringcolumn(1) eq word(sizes,i) ? idx(stringcolumn(2)) + off(i) : NaN):3 \
       with points pt 7 ps 1.6 lc i title sprintf("%s instances", word(sizes,i)), \
     for [i=1:3] csv using (stringcolumn(1) eq word(sizes,i) && $4 >= 0 ? idx(stringcolumn(2)) + off(i) : NaN):3:(sprintf("%d", $4)) \
       with labels offset 0,-1.1 font ",9" notitle
