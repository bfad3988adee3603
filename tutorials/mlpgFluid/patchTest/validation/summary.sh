#!/bin/bash
# Usage: validation/summary.sh [ERRORS [HISTOGRAM]]
# The patch-test checks from postProcessing/patchTest/errors.dat (default;
# the committed validation/errors.dat is the run of the README):
#   E3-06 least-squares slope of log Er against log dl, per scheme and k
#   E3-07 mean wall error, E3-08 maximum error, at dl = 0.01, k = 0.3
#   E3-09 Er of each improved scheme <= that of `original` at every (dl, k)
# and the plots errors.png, histogram.png beside this script (gnuplot).
cd "${0%/*}/.." || exit 1
err=${1:-postProcessing/patchTest/errors.dat}
hist=${2:-postProcessing/patchTest/histogram.dat}
[ -f "$err" ] || { echo "summary.sh: no $err (run ./Allrun)" >&2; exit 1; }
echo "E3-06: slope of log Er against log dl (least squares over the spacings)"
awk '!/^#/ { k = $1 " " $2; n[k]++; x = log($3); y = log($5)
             sx[k] += x; sy[k] += y; sxx[k] += x * x; sxy[k] += x * y }
     END { for (k in n) printf "  %-24s slope %.2f (%d spacings)\n", k,
           (n[k] * sxy[k] - sx[k] * sy[k]) / (n[k] * sxx[k] - sx[k] * sx[k]), n[k] }' "$err" | sort
echo "E3-07 / E3-08 at dl = 0.01, k = 0.3 (mean over the seeds):"
awk '!/^#/ && $2 == "0.30" && $3 == "0.010000" {
        printf "  %-20s Er %.3e  wall mean %.3e  max %.3e\n", $1, $5, $7, $8 }' "$err"
echo "E3-09: (dl, k) where a scheme's Er exceeds the original scheme's:"
awk '!/^#/ { e[$1 " " $2 " " $3] = $5; s[$1] = 1; c[$2 " " $3] = 1 }
     END { for (sc in s) { if (sc == "original") continue; bad = 0; tot = 0
             for (q in c) { tot++; if (e[sc " " q] > e["original " q]) { bad++; lst = lst " (" q ")" } }
             printf "  %-20s %d of %d%s\n", sc, bad, tot, bad ? ":" lst : ""; lst = "" } }' "$err"
command -v gnuplot > /dev/null || { echo "(gnuplot not found: no plots)"; exit 0; }
gnuplot <<GP
set terminal pngcairo size 1200,500
set output 'validation/errors.png'
set multiplot layout 1,2
set logscale xy; set grid; set key bottom right
set xlabel 'dl'; set ylabel 'Er'
set title 'Patch test, k = 0.3 (mean of the seeds)'
plot for [s in "improved improvedConsistent original"] '$err' u (strcol(1) eq s && \$2 == 0.3 ? \$3 : 1/0):5 w lp t s, \
     x**2 * 20 dt 2 lc rgb 'gray' t 'slope 2', x * 0.25 dt 3 lc rgb 'gray' t 'slope 1'
set title 'Er at dl = 0.01 against k'
unset logscale x; set xlabel 'k'
plot for [s in "improved improvedConsistent original"] '$err' u (strcol(1) eq s && \$3 == 0.01 ? \$2 : 1/0):5 w lp t s
unset multiplot
set output 'validation/histogram.png'
set terminal pngcairo size 700,500
unset logscale; set logscale y; set xlabel 'e_i / max e_i'; set ylabel 'nodes'
set title 'Nodes per error band, dl = 0.01, k = 0.3 (thesis Fig. 4.6)'
set style data histograms; set style fill solid 0.6; set key top right
plot '$hist' u 4:xtic(sprintf("%.1f", \$2)) t 'improved', '' u 5 t 'improvedConsistent', '' u 6 t 'original'
GP
echo "plots: validation/errors.png validation/histogram.png"
