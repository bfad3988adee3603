#!/usr/bin/env bash
# mpsWorkPrecision.sh [RESOLUTIONS] — work-precision of mpsFluid on the 2-D
# Martin & Moyce dam break (tutorials/mpsFluid/damBreak2D), not a test.
# For each resolution a/N (default N = "10 20 30 40"), each r_e set
#   cheap  2.1 / 2.1 / 3.1  (number density / gradient / Laplacian, dp)
#   sjtu   2.1 / 2.1 / 4.0
#   paper  4.1 / 4.1 / 4.1
# and each PPE tolerance (1e-4, 1e-8): runs the case, takes the error
# (RMS of the surge front Z plus RMS of the column height H, validation/
# compare.sh, without and with the time shift SHIFT (default 0.2) on the
# simulated T and tau that the data README allows) and the cost (CPU seconds per simulated second,
# from the process's user+system time), prints a table with the settings on
# the Pareto front marked '*', and draws work_precision.png (gnuplot) in the
# current directory. One thread per run (OMP_NUM_THREADS=1) for stable
# timings. a/40 with the paper radii takes minutes.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
RES=${1:-"10 20 30 40"}
SHIFT=${SHIFT:-0.2}   # the experiment's release delay on T (data README)
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
export OMP_NUM_THREADS=1
OUT="$TMP/table"
set_key() { sed -i "s|^\( *$2\) .*|\1 $3;|" "$1"; }
for N in $RES; do
  dp=$(awk -v n=$N 'BEGIN { printf "%.10g", 0.05715 / n }')
  for set in "cheap 2.1 2.1 3.1" "sjtu 2.1 2.1 4.0" "paper 4.1 4.1 4.1"; do
    set -- $set
    for tol in 1e-4 1e-8; do
      c="$TMP/a${N}_$1_$tol"
      cp -r "$ROOT/tutorials/mpsFluid/damBreak2D" "$c"
      set_key "$c/system/particleDict" dp "$dp"
      set_key "$c/system/mpsSchemes" reNumberDensity "$2"
      set_key "$c/system/mpsSchemes" reGradient "$3"
      set_key "$c/system/mpsSchemes" reLaplacian "$4"
      set_key "$c/system/mpsSolution" tolerance "$tol"
      (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || { echo "a/$N $1 $tol: genParticles failed"; continue; }
      /usr/bin/env time -f "%U %S" -o "$c/time" "$ROOT/bin/mpsFluid" -case "$c" > "$c/log.mpsFluid" 2>&1
      cpu=$(awk '{ print $1 + $2 }' "$c/time" 2>/dev/null)
      if ! grep -q '^End' "$c/log.mpsFluid"; then echo "a/$N $1 $tol: mpsFluid failed"; continue; fi
      e=$("$ROOT/tutorials/mpsFluid/damBreak2D/validation/compare.sh" "$c" | awk '/rmsZ/ { z = $2 } /rmsH/ { h = $2 } END { print z, h, z + h }')
      es=$("$ROOT/tutorials/mpsFluid/damBreak2D/validation/compare.sh" "$c" "$SHIFT" | awk '/rmsZ/ { z = $2 } /rmsH/ { h = $2 } END { print z + h }')
      echo "a/$N $1 $tol $cpu $e $es" | awk '{ printf "%-6s %-6s %-6s %10.3f %8.4f %8.4f %8.4f %8.4f\n", $1, $2, $3, $4 / 0.2, $5, $6, $7, $8 }' >> "$OUT"
    done
  done
done
# Pareto fronts, of the error and of the shifted error: no other run is
# both cheaper and more accurate.
awk 'function front(i, col,   j) { for (j = 1; j <= NR; j++)
       if (j != i && c[j] <= c[i] && e[j, col] <= e[i, col] && (c[j] < c[i] || e[j, col] < e[i, col])) return " "
       return "*" }
  { c[NR] = $4; e[NR, 7] = $7; e[NR, 8] = $8; l[NR] = $0 } END {
  printf "%-6s %-6s %-6s %10s %8s %8s %8s %8s %s\n", "res", "re", "tol", "cpu_s/s", "rmsZ", "rmsH", "error", "error_s", "pareto(error, error_s)"
  for (i = 1; i <= NR; i++) print l[i], front(i, 7) front(i, 8) }' "$OUT" | tee work_precision.txt
gnuplot <<GP 2>/dev/null && echo "wrote work_precision.png"
set terminal pngcairo size 1200,520 noenhanced
set output 'work_precision.png'
set multiplot layout 1,2
set logscale xy; set xlabel 'CPU seconds per simulated second'
set key top right
set ylabel 'rms Z + rms H (Martin & Moyce), no shift'
plot for [s in "cheap sjtu paper"] for [t in "1e-4 1e-8"] '$OUT' u (strcol(2) eq s && strcol(3) eq t ? \$4 : 1/0):7 w p pt 7 t s.' tol '.t
set ylabel 'the same with T, tau + $SHIFT'
plot for [s in "cheap sjtu paper"] for [t in "1e-4 1e-8"] '$OUT' u (strcol(2) eq s && strcol(3) eq t ? \$4 : 1/0):8 w p pt 7 t s.' tol '.t
unset multiplot
GP
