#!/bin/sh
# e507.sh RUN... — the numbers of E5-07 (doc/theory.md) from the fronts
# that runAll wrote (validation/fronts_<RUN>.dat), over 0.1-0.5 s, before
# the soil reaches the far wall (0.6-0.7 s): per run the soil front at
# 0.3 s [m], the mean height of the soil's leading edge [m] (a blunt,
# "carpet" front is high) and the airborne soil particles summed over the
# snapshots (splash).
cd "$(dirname "$0")" || exit 1
echo "# run Xs_0.3s_m mean_leading_edge_height_m airborne_summed   (0.1-0.5 s, validation/e507.sh)"
for r in "$@"; do
    awk -v r="$r" '!/^#/ && $1 >= 0.1 - 1e-9 && $1 <= 0.5 + 1e-9 { n++; h += $3; a += $4 }
        !/^#/ && $1 > 0.3 - 1e-9 && $1 < 0.3 + 1e-9 { x = $2 }
        END { printf "%s %s %.4f %d\n", r, x, h / n, a }' "fronts_$r.dat"
done
