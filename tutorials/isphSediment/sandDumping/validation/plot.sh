#!/bin/bash
# Usage: validation/plot.sh [RUN]
# validation/sandDumping.png from the committed validation/series_case<N>.dat
# (cloud.sh): the cloud's front velocity omega_c against t and its width W
# against its descent Z, the four cases of Pan 2022 Table 1, with the
# single grains' settling velocities omega_s (Table 1). With RUN (a case
# directory that has run case 1, and case 2 in RUN/case2), the thesis's
# pictures: validation/alpha_cases12.png (alpha_s of cases 1 and 2 at 1
# and 2 s, its Figs. 5.12-5.13) and validation/case2_fields.png (case 2:
# alpha_s, the dynamic pressure p - rho_f g (H - y), H = 1 m, and the
# vorticity dv/dx - du/dy of the velocities averaged on cells of dl, at
# 0.25, 0.5, 0.75, 1, 2 s, its Fig. 5.15).
cd "${0%/*}" || exit 1
root=${MPSDEM_DIR:-$(cd ../../../.. && pwd)}
plots=""; wplots=""
ws=(0 0.1260 0.4952 0.1961 0.4952)
for n in 1 2 3 4; do
    f=series_case$n.dat
    [ -f "$f" ] || continue
    plots="$plots${plots:+, }'$f' u 1:4 w lp pt 7 ps 0.5 lc $n t 'case $n', ${ws[$n]} w l dt 2 lc $n notitle"
    wplots="$wplots${wplots:+, }'$f' u 2:3 w lp pt 7 ps 0.5 lc $n t 'case $n'"
done
gnuplot <<GP
set terminal pngcairo size 1100,450
set output 'sandDumping.png'
set multiplot layout 1,2 title 'Sand dumped into still water (isphSediment; dashed: single-grain omega_s)'
set grid; set key top right
set xlabel 't [s]'; set ylabel 'omega_c = dZ/dt [m/s]'; set xrange [0:3]; set yrange [0:0.9]
plot $plots
set key top left
set xlabel 'Z (descent of the front) [m]'; set ylabel 'W (width of the cloud) [m]'; set xrange [0:1]; set yrange [0:0.5]
plot $wplots
unset multiplot
GP
echo "wrote validation/sandDumping.png"
[ -n "$1" ] || exit 0
run=$(cd "$OLDPWD" && cd "$1" && pwd)
# fields of a run directory at time t: x y alpha_s p_dyn, and the
# vorticity dv/dx - du/dy of the velocities averaged on cells of dl
fields() { # $1 case dir, $2 time, $3 output prefix
    "$root/bin/vtuInfo" -dump "$1/$2/fluid.vtu" | awk -v o="$3" '
        /^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 {
            print $1, $2, $c["alpha.sediment"], $c["pressure"] - 1000 * 9.8 * (1 - $2) > (o ".pts")
            i = int($1 / 0.01); j = int($2 / 0.01); u[i, j] += $c["velocity_0"]; v[i, j] += $c["velocity_1"]; n[i, j]++ }
        END { for (k in n) { split(k, ij, SUBSEP); a = ij[1]; b = ij[2]
                  if (!(((a + 1) SUBSEP b) in n) || !(((a - 1) SUBSEP b) in n) || !((a SUBSEP (b + 1)) in n) || !((a SUBSEP (b - 1)) in n)) continue
                  w = (v[a + 1, b] / n[a + 1, b] - v[a - 1, b] / n[a - 1, b]) / 0.02 - (u[a, b + 1] / n[a, b + 1] - u[a, b - 1] / n[a, b - 1]) / 0.02
                  print (a + 0.5) * 0.01, (b + 0.5) * 0.01, w > (o ".vort") } }'
}
for t in 1 2; do fields "$run" $t "c1_$t"; done
for t in 0.25 0.5 0.75 1 2; do fields "$run/case2" $t "c2_$t"; done
gnuplot <<GP
set terminal pngcairo size 1000,900
set output 'alpha_cases12.png'
set multiplot layout 2,2 title 'alpha_s of the sand cloud (isphSediment; the thesis: a double peak in case 1, none in case 2)'
set size ratio -1; set xrange [0.2:0.8]; set yrange [0.0:1.02]; unset key; set cbrange [0:0.05]
do for [c in 'c1 c2'] { do for [t in '1 2'] {
    set title sprintf('case %s, t = %s s', c[2:2], t); plot c.'_'.t.'.pts' u 1:2:3 w p pt 7 ps 0.3 lc palette } }
unset multiplot
GP
gnuplot <<GP
set terminal pngcairo size 1600,950
set output 'case2_fields.png'
set multiplot layout 3,5 title 'Case 2: alpha_s, dynamic pressure p - rho_f g (H - y) [Pa] and vorticity [1/s] (isphSediment)'
set size ratio -1; set xrange [0.2:0.8]; set yrange [0.0:1.02]; unset key
set cbrange [0:0.05]
do for [t in '0.25 0.5 0.75 1 2'] { set title sprintf('alpha_s, t = %s s', t); plot 'c2_'.t.'.pts' u 1:2:3 w p pt 7 ps 0.25 lc palette }
set palette defined (-1 'blue', 0 'white', 1 'red'); set cbrange [-60:60]
do for [t in '0.25 0.5 0.75 1 2'] { set title sprintf('dynamic p, t = %s s', t); plot 'c2_'.t.'.pts' u 1:2:4 w p pt 7 ps 0.25 lc palette }
set cbrange [-4:4]
do for [t in '0.25 0.5 0.75 1 2'] { set title sprintf('vorticity, t = %s s', t); plot 'c2_'.t.'.vort' u 1:2:3 w p pt 5 ps 0.3 lc palette }
unset multiplot
GP
rm -f c1_*.pts c1_*.vort c2_*.pts c2_*.vort
echo "wrote validation/alpha_cases12.png, validation/case2_fields.png"
