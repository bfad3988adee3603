#!/usr/bin/env bash
# mpsMemory.sh [DP ...] — peak memory and time per particle-step of
# mpsFluid on the 3-D Kleefsman tank (tutorials/mpsFluid/damBreakObstacle)
# with `neighbourDistances stored` and `measured` (system/mpsSchemes).
#
# Per DP (default 0.04 0.025 0.02): a copy of the tutorial with that dp,
# fixed steps of 5e-4 s, two threads (THREADS=). Memory: 2 steps, the
# `peak memory` line of the final statistics. Time (ROUNDS > 0, default
# 3): 20 steps, ROUNDS runs of each setting taken in turn (the machine's
# speed drifts within minutes), the fastest per phase from the
# `time per particle-step` line. OLD=<bin dir> adds the programs of another
# build (run with its own default) as the first setting. Prints one table
# per DP; state the machine's load beside the numbers.
#
#   test/bench/mpsMemory.sh 0.025
#   OLD=/path/to/old/bin ROUNDS=4 test/bench/mpsMemory.sh 0.025
set -u
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
THREADS=${THREADS:-2}; ROUNDS=${ROUNDS:-3}; OLD=${OLD:-}
[ $# -gt 0 ] || set -- 0.04 0.025 0.02
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
settings="new:stored new:measured"; [ -n "$OLD" ] && settings="old:default $settings"
bindir() { [ "$1" = old ] && echo "$OLD" || echo "$ROOT/bin"; }
run() { # DIR SETTING STEPS -> log.<setting>
    local d=$1 b=${2%%:*} m=${2#*:}
    (cd "$d" && rm -rf 0.* [1-9]* postProcessing fluid.pvd
     "$ROOT/bin/dictTool" system/controlDict -set endTime=$(awk -v n=$3 'BEGIN { print n * 5e-4 }') > /dev/null
     cp system/mpsSchemes.orig system/mpsSchemes
     [ "$m" = default ] || "$ROOT/bin/dictTool" system/mpsSchemes -set neighbourDistances=$m -new > /dev/null
     OMP_NUM_THREADS=$THREADS "$(bindir $b)/mpsFluid" > "log.${2/:/.}" 2>&1) \
        || { echo "mpsMemory: mpsFluid ($2) failed in $d, see log.${2/:/.}" >&2; exit 1; }
}
for dp in "$@"; do
    d="$TMP/dp$dp"
    cp -r "$ROOT/tutorials/mpsFluid/damBreakObstacle" "$d"
    "$ROOT/bin/dictTool" "$d/system/particleDict" -set dp=$dp > /dev/null || exit 1
    "$ROOT/bin/dictTool" "$d/system/controlDict" -set adjustTimeStep=no -set deltaT=5e-4 \
        -set writeInterval=1 > /dev/null || exit 1
    cp "$d/system/mpsSchemes" "$d/system/mpsSchemes.orig"
    (cd "$d" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || { echo "genParticles failed" >&2; exit 1; }
    echo "== dp $dp m, $THREADS threads, load $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "setting          particles  peak MB  kB/particle"
    for s in $settings; do
        run "$d" $s 2
        awk -v s=$s '/^ *particles / && !n { n = $2 } /peak memory/ { mb = $3; kb = $5 }
                     END { gsub(/\(/, "", kb); printf "%-16s %9d %8s %12s\n", s, n, mb, kb }' "$d/log.${s/:/.}"
    done
    [ "$ROUNDS" -gt 0 ] || continue
    for r in $(seq "$ROUNDS"); do
        for s in $settings; do
            run "$d" $s 20
            grep "time per particle-step" "$d/log.${s/:/.}" | sed "s/^/$s /" >> "$d/times"
        done
    done
    echo "time per particle-step [us], fastest of $ROUNDS:"
    awk '{ s = $1; for (k = 6; k < NF; k += 2) { v = $(k + 1) + 0; key = s SUBSEP $k
                                              if (!(key in m) || v < m[key]) m[key] = v
                                              if (!(s in seen)) { seen[s] = ++ns; order[ns] = s }
                                              if (!($k in ph)) { ph[$k] = ++np; pname[np] = $k } } }
         END { printf "%-16s", "setting"; for (p = 1; p <= np; p++) printf " %11s", pname[p]; print ""
               for (i = 1; i <= ns; i++) { printf "%-16s", order[i]
                   for (p = 1; p <= np; p++) printf " %11.3f", m[order[i], pname[p]]; print "" } }' "$d/times"
done
