#!/bin/bash
# Usage: validation/plot.sh
# validation/batchSettling.png from the committed
# validation/series_alpha<A>.dat (interface.sh): the descent of the
# clear-water interface since 0.5 s against time for alpha_s0 = 0.05, 0.1,
# 0.2, with the model-consistent hindered velocity alpha_f w (dashed, from
# each file's "# model" line), and the bulk's sediment and water
# velocities against the model's -alpha_f w and alpha_s w.
cd "${0%/*}" || exit 1
plots=""; vplots=""; n=0
for a in 0.05 0.1 0.2; do
    f=series_alpha$a.dat
    [ -f "$f" ] || continue
    n=$((n + 1))
    vm=$(awk '/^# model/ { print $8 }' "$f"); wm=$(awk '/^# model/ { print $(NF - 1) }' "$f")
    y0=$(awk '!/^#/ && $1 == 0.5 { print $2 }' "$f")
    plots="$plots${plots:+, }'$f' u 1:($y0 - \$2) w p pt 7 ps 0.7 lc $n t 'alpha_s0 = $a', (x - 0.5) * $vm w l dt 2 lc $n notitle"
    vplots="$vplots${vplots:+, }'$f' u 1:4 w lp pt 7 ps 0.5 lc $n t 'u_s, alpha_s0 = $a', '$f' u 1:5 w lp pt 6 ps 0.5 lc $n t 'u_f', -$vm w l dt 2 lc $n notitle, $a * $wm w l dt 2 lc $n notitle"
done
[ "$n" -gt 0 ] || { echo "plot.sh: no validation/series_alpha*.dat" >&2; exit 1; }
gnuplot <<GP
set terminal pngcairo noenhanced size 1100,450
set output 'batchSettling.png'
set multiplot layout 1,2 title 'Batch settling of a uniform suspension (isphSediment; dashed: model-consistent hindered settling)'
set grid; set key top left
set xlabel 't [s]'; set ylabel 'descent of the interface since 0.5 s [m]'; set xrange [0:6]
plot $plots
set key bottom right
set ylabel 'bulk velocity [m/s]'
plot $vplots
unset multiplot
GP
echo "wrote validation/batchSettling.png"
