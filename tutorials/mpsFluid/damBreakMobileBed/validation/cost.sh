#!/bin/sh
# cost.sh RUN... — particle-steps per second of runs of damBreakMobileBed
# (from the end-of-run statistics of RUN/log.mpsFluid), and each against
# the first run given: the cost of the soil model next to the bed made of
# water (validation/runAll: solid_1900 liquid_1900 water).
cd "$(dirname "$0")/.." || exit 1
echo "# run particles steps wall_s particle_steps_per_s relative_to_$1"
ref=
for r in "$@"; do
    awk -v r="$r" '/^    steps / { st = $2 } /^    particles / { np = $2 }
        /particle-steps\/s/ { ps = $2; w = $(NF - 1) }
        END { printf "%s %d %d %s %s\n", r, np, st, w, ps }' "$r/log.mpsFluid"
done | awk 'NR == 1 { ref = $5 } { printf "%s %.3f\n", $0, $5 / ref }'
