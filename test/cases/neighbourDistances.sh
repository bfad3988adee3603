#!/usr/bin/env bash
# neighbourDistances.sh — `neighbourDistances measured` (system/mpsSchemes:
# the neighbour list keeps positions instead of distances, the operators
# measure them again and compute the kernel weights where they read them)
# gives the results of `stored` to the bit, with less memory.
#
# The 3-D Kleefsman tank (tutorials/mpsFluid/damBreakObstacle, dp 0.04 m,
# 45 k particles: r_e 2.1 / 3.1 dp, predictor, skin 0.5 dp), 12 fixed
# steps of 5e-4 s (one list build, then updates), with every reader of the
# distances and weights switched on: shifting lind2012 (and xu2009 in a
# second pair), dummyPressure extrapolated, freeSurface pressure
# extrapolated, pressureGradient corrected. Two threads (the operators
# must give the same sums per thread as with stored distances).
#   - every .vtu and function-object file byte-identical (cmp);
#   - peak memory of `measured` below `stored` (measured 2026-11-28 at
#     dp 0.025 m: 1.40 against 2.12 kB per particle).
NAME=neighbourDistances; . "$(dirname "$0")/lib/case.sh"
need_bins genParticles mpsFluid dictTool
export OMP_NUM_THREADS=2
TUT="$ROOT/tutorials/mpsFluid/damBreakObstacle"
set_keys() { # DIR FILE KEY=VALUE... (new keys allowed)
    local d=$1 f=$2 a=(); shift 2
    for kv in "$@"; do a+=(-set "$kv"); done
    "$ROOT/bin/dictTool" "$d/$f" "${a[@]}" -new > /dev/null
}
base="$TMP/base"
cp -r "$TUT" "$base"
(cd "$base" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) \
    || { fail neighbourDistances_setup "genParticles failed"; exit 1; }
set_keys "$base" system/controlDict adjustTimeStep=no deltaT=5e-4 endTime=0.006 \
    writeControl=timeStep writeInterval=4 \
    || { fail neighbourDistances_setup "dictTool refused system/controlDict"; exit 1; }
peak() { awk '/peak memory/ { print $3 }' "$1/log.mpsFluid"; }
for shift in lind2012 xu2009; do
    for mode in stored measured; do
        c="$TMP/$shift.$mode"
        cp -r "$base" "$c"
        set_keys "$c" system/mpsSchemes shifting=$shift neighbourDistances=$mode \
            dummyPressure=extrapolated freeSurface/pressure=extrapolated \
            pressureGradient=corrected \
            || { fail neighbourDistances_setup "dictTool refused system/mpsSchemes"; exit 1; }
        if ! (cd "$c" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1) \
           || ! grep -q '^End' "$c/log.mpsFluid"; then
            fail "neighbourDistances_run_${shift}_$mode" \
                 "$(grep -A2 FATAL "$c/log.mpsFluid" | head -3 | tr '\n' ' ')"
            exit 1
        fi
    done
    a="$TMP/$shift.stored"; b="$TMP/$shift.measured"
    n=0; diff=""
    while IFS= read -r f; do
        n=$((n + 1))
        cmp -s "$a/$f" "$b/$f" || diff="$diff $f"
    done < <(cd "$a" && find [0-9]* postProcessing -type f \( -name '*.vtu' -o -name '*.dat' \) | sort)
    [ "$(cd "$b" && find [0-9]* postProcessing -type f \( -name '*.vtu' -o -name '*.dat' \) | wc -l)" -eq "$n" ] \
        || diff="$diff (file count)"
    if [ $n -ge 4 ] && [ -z "$diff" ]; then
        pass "neighbourDistances_identical_$shift"
    else
        fail "neighbourDistances_identical_$shift" "$n files, differ:$diff"
    fi
    ps=$(peak "$a"); pm=$(peak "$b")
    echo "    $shift: peak memory stored $ps MB, measured $pm MB"
    awk -v s="$ps" -v m="$pm" 'BEGIN { exit !(s > 0 && m > 0 && m < s) }' \
        && pass "neighbourDistances_memory_$shift" \
        || fail "neighbourDistances_memory_$shift" "measured $pm MB, stored $ps MB"
done
exit $((fails > 0))
