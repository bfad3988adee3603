#!/bin/bash
# Usage: validation/plot.sh
# The committed profiles validation/profile_dl<dl>.dat at t = 5 s against
# the hindered-settling solution (5.50) and the start profile (5.51):
# validation/settling.png.
cd "${0%/*}" || exit 1
awk 'BEGIN { for (y = 0; y <= 0.5; y += 0.001) {
    f0 = (y < 0.1) ? 0 : 0.0005 * (1 + cos(2 * 3.141592653589793 * ((y - 0.1) / 0.4 - 0.5)))
    p = y; for (k = 0; k < 50; k++) { q = (p < 0.1 || p > 0.5) ? 0 : 0.0005 * (1 + cos(2 * 3.141592653589793 * ((p - 0.1) / 0.4 - 0.5)))
                                     p = y + 0.0159 * (1 - q)^1.65 * 5 }
    f = (p < 0.1 || p > 0.5) ? 0 : 0.0005 * (1 + cos(2 * 3.141592653589793 * ((p - 0.1) / 0.4 - 0.5)))
    print y, f0, f } }' > exact.tmp
files=$(ls profile_dl*.dat | sort -t l -k2 -g -r)
plot="'exact.tmp' u 2:1 w l dt 2 lc rgb 'gray' t 't = 0 (5.51)', 'exact.tmp' u 3:1 w l lw 2 lc rgb 'black' t 't = 5 s (5.50)'"
for f in $files; do d=${f#profile_dl}; d=${d%.dat}; plot="$plot, '$f' u 2:1 w lp ps 0.6 t 'dl = $d m'"; done
gnuplot <<GP
set terminal pngcairo size 700,600
set output 'settling.png'
set grid; set key top right
set xlabel 'alpha_s (mean of each particle row)'; set ylabel 'x_2 [m]'
set title 'Sediment settling in still water, t = 5 s (isphSediment)'
plot $plot
GP
rm -f exact.tmp
echo "wrote validation/settling.png"
