#!/usr/bin/env bash
# validation/fronts.sh [RUN...] — water and sediment fronts of finished runs
# of this tutorial (default: every model*-dp* directory), the paper's Figs.
# 11-14 and check E1-20:
#   - a table of both fronts at 0.1, 0.15, 0.2, 0.25 and 0.3 s per run;
#   - E1-20: the spread (max - min) of each front over the Model B runs at
#     t = 0.15 s, relative to their mean (target < 5 %), when there are two
#     or more Model B runs;
#   - validation/fronts.png (gnuplot): both fronts against time, all runs.
# Fronts (function objects fluidFront and sedimentFront): water, the largest
# x of a fluid particle with n >= 0.5 n0; sediment, the leading grain of the
# largest touching pack (doc/theory.md A.12.2 [P]).
cd "${0%/*}/.." || exit 1
runs=("$@")
[ ${#runs[@]} -eq 0 ] && runs=(model*-dp*/)
runs=("${runs[@]%/}")
at() { # file time: the front at the last row not after time (nan past the end)
    awk -v t="$2" '!/^#/ { e = $1; if ($1 <= t + 1e-9) v = $2 }
        END { print (v == "" || e < t - 1e-9 ? "nan" : v) }' "$1"
}
printf "%-22s %-6s" run front
for t in 0.1 0.15 0.2 0.25 0.3; do printf " %8s" "$t s"; done
echo
for r in "${runs[@]}"; do
    for f in fluidFront sedimentFront; do
        file="$r/postProcessing/$f/0/front.dat"
        [ -f "$file" ] || { echo "$r: no $file"; continue 2; }
        printf "%-22s %-6s" "$r" "${f%Front}"
        for t in 0.1 0.15 0.2 0.25 0.3; do printf " %8.4f" "$(at "$file" $t)"; done
        echo
    done
done
bruns=()
for r in "${runs[@]}"; do
    [ "$(sed -n 's/^model *\([AB]\);.*/\1/p' "$r/system/couplingDict" 2>/dev/null)" = B ] && bruns+=("$r")
done
if [ ${#bruns[@]} -ge 2 ]; then
    for f in fluidFront sedimentFront; do
        for r in "${bruns[@]}"; do at "$r/postProcessing/$f/0/front.dat" 0.15; done |
            awk -v f="${f%Front}" '{ v[NR] = $1; s += $1; if (NR == 1 || $1 < lo) lo = $1; if (NR == 1 || $1 > hi) hi = $1 }
                END { m = s / NR; printf "E1-20 %s front at 0.15 s over %d Model B runs: spread %.4f m = %.1f %% of the mean %.4f m (target < 5 %%)\n", f, NR, hi - lo, 100 * (hi - lo) / m, m }'
    done
fi
command -v gnuplot > /dev/null || { echo "gnuplot not found: no plot"; exit 0; }
plots=""
for r in "${runs[@]}"; do
    plots="$plots '$r/postProcessing/fluidFront/0/front.dat' u 1:2 w l t '$r water',"
    plots="$plots '$r/postProcessing/sedimentFront/0/front.dat' u 1:2 w l dt 2 t '$r sediment',"
done
gnuplot <<EOF
set terminal png size 900,600
set output 'validation/fronts.png'
set xlabel 't [s]'; set ylabel 'front x [m]'; set grid; set key left top
plot ${plots%,}
EOF
echo "validation/fronts.png written"
