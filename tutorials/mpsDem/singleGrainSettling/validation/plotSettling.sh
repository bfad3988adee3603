#!/usr/bin/env bash
# plotSettling.sh [t0] [PNG] — validation/settling.png (gnuplot) after
# ./Allrun: the grain's lab-frame settling speed |v_y| (every written
# dem.vtu, validation/grainHistory.sh) and its slip |u_k - v_k| (the
# couplingForces function object, every 10 steps) against time, with
#   - the drag-balance slip at the mean eps_k after t0 (default 0.2 s)
#     measured by couplingForces (validation/balanceSlip.awk), and
#   - the single-sphere terminal speed 0.343 m/s (eps_k = 1; E1-14).
# The title gives the means after t0 (as validation/terminalVelocity.sh).
cd "${0%/*}/.." || exit 1
t0=${1:-0.2}
png=${2:-validation/settling.png}
f=postProcessing/grain/0/couplingForces.dat
[ -f "$f" ] || { echo "plotSettling.sh: $f missing (run ./Allrun first)" >&2; exit 1; }
command -v gnuplot > /dev/null || { echo "plotSettling.sh: gnuplot not found" >&2; exit 1; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
validation/grainHistory.sh > "$tmp/grain.dat"
[ -s "$tmp/grain.dat" ] || { echo "plotSettling.sh: no <time>/dem.vtu" >&2; exit 1; }
eps=$(awk -v t0="$t0" '!/^#/ && $1 >= t0 { n++; e += $9 } END { if (n) printf "%.4f", e / n }' "$f")
[ -n "$eps" ] || { echo "plotSettling.sh: no couplingForces rows after $t0 s" >&2; exit 1; }
bal=$(awk -v e="$eps" -f validation/balanceSlip.awk)
one=$(awk -v e=1 -f validation/balanceSlip.awk)
vm=$(awk -v t0="$t0" '$1 >= t0 { n++; s -= $5 } END { printf "%.4f", s / n }' "$tmp/grain.dat")
sm=$(awk -v t0="$t0" '!/^#/ && $1 >= t0 { n++; s += $8 } END { printf "%.4f", s / n }' "$f")
echo "after $t0 s: mean settling speed $vm m/s, mean slip $sm m/s at mean eps_k $eps;" \
     "balance slip at eps_k = $eps: $(printf %.4f "$bal") m/s, single sphere $(printf %.4f "$one") m/s"
gnuplot <<EOF
set terminal pngcairo size 1000,600 font ',11'
set output '$png'
set title sprintf("singleGrainSettling (2.7 mm glass bead in water, Model B): means after t_0 = $t0 s\n settling speed %s m/s (%+.1f %% of 0.343), slip %s m/s (%+.1f %% of the balance slip at {/Symbol e}_k = $eps)", \
    '$vm', 100 * ($vm / $one - 1), '$sm', 100 * ($sm / $bal - 1))
set xlabel 'time t [s]'; set ylabel 'speed [m/s]'; set grid
set yrange [0:0.45]; set xrange [0:*]
set key bottom right box opaque
set arrow from $t0, graph 0 to $t0, graph 1 nohead dt 4 lc 'gray40'
set label 't_0' at $t0, graph 0.04 offset 0.5,0
plot '$f' u 1:8 w l lw 1.5 lc rgb '#1f77b4' t 'slip |u_k - v_k| (couplingForces)', \
     '$tmp/grain.dat' u 1:(-\$5) w lp pt 7 ps 0.7 lw 2 lc rgb '#d62728' t 'settling speed |v_y| (dem.vtu)', \
     $bal dt 2 lw 2 lc 'black' t sprintf('drag balance: slip at {/Symbol e}_k = $eps, %.4f m/s', $bal), \
     $one dt 3 lw 2 lc rgb '#2ca02c' t sprintf('single sphere ({/Symbol e}_k = 1): %.4f m/s', $one)
EOF
echo "$png written"
