#!/usr/bin/env bash
# obstacleSediment.sh — tutorials/mpsDem/obstacleSediment (issue 17), short:
#   clearWater   ./Allrun 0 (no grains, mpsFluid alone) writes the same
#                fluid.vtu and the same gauge, probe and force files, byte
#                for byte, as tutorials/mpsFluid/damBreakObstacle run with
#                the same fixed deltaT (H_s = 0 is that case)
#   coupled      ./Allrun 0.071 (5760 grains, mpsFluid + demSolid in
#                tandem, Model B) reaches End in both programs over 5
#                coupling steps; dem.vtu holds 5760 grains on the reservoir
#                floor; the grains' load on the box and the sediment front
#                are written; the tandem leaves no channel segment
#   badHs        ./Allrun 0.1 is refused with the valid heights, nothing run
NAME=obstacleSediment
. "$(dirname "$0")/lib/tandem.sh"
export MPSDEM_DIR="$ROOT"
TUT="$ROOT/tutorials/mpsDem/obstacleSediment"
short() { # CASE ENDTIME: end early
    "$ROOT/bin/dictTool" "$1/system/controlDict" -set "endTime=$2" > /dev/null; }

# ---- H_s = 0 against damBreakObstacle ---------------------------------------
o="$TMP/obs"; cp -r "$TUT" "$o"; short "$o" 0.005
c="$TMP/clear"; cp -r "$ROOT/tutorials/mpsFluid/damBreakObstacle" "$c"
"$ROOT/bin/dictTool" "$c/system/controlDict" -set endTime=0.005 -set adjustTimeStep=no \
    -set deltaT=5e-4 -set writeControl=runTime > /dev/null
if (cd "$o" && ./Allrun 0 > log.Allrun 2>&1) && (cd "$c" && ./Allrun > log.Allrun 2>&1); then
    diffs=""
    for f in 0/fluid.vtu 0.005/fluid.vtu postProcessing/heights/0/waveGauges.dat \
             postProcessing/pressure/0/probes.dat postProcessing/load/0/forces.dat \
             postProcessing/waterFront/0/front.dat; do
        [ -s "$c/$f" ] && cmp -s "$c/$f" "$o/Hs0/$f" || diffs="$diffs $f"
    done
    [ -z "$diffs" ] && pass obstacleSediment_clearWater \
        || fail obstacleSediment_clearWater "differ or missing:$diffs"
else
    fail obstacleSediment_clearWater "a run failed: $(fatal_of "$o/Hs0") $(fatal_of "$c")"
fi

# ---- H_s = 0.071 coupled ----------------------------------------------------
o="$TMP/obs2"; cp -r "$TUT" "$o"; short "$o" 0.0025
ch="mpsdem-obstacle-test-$$"
echo "channel $ch;" >> "$o/system/couplingDict"
sed -i 's/^timeout .*/timeout 120;/' "$o/system/couplingDict"
if (cd "$o" && timeout 600 ./Allrun 0.071 > log.Allrun 2>&1) \
   && grep -q '^End' "$o/Hs0.071/log.mpsFluid" && grep -q '^End' "$o/Hs0.071/log.demSolid"; then
    pass obstacleSediment_coupled
    n=$("$ROOT/bin/vtuInfo" -dump "$o/Hs0.071/0.0025/dem.vtu" 2>/dev/null \
        | awk '$1 ~ /^[0-9]/ && $1 > 1.99 && $1 < 3.22 && $3 > 0.012 && $3 < 0.064 { n++ } END { print n + 0 }')
    [ "$n" = 5760 ] && pass obstacleSediment_grains \
        || fail obstacleSediment_grains "$n of 5760 grains on the reservoir floor at 0.0025 s"
    for f in solidLoad/0/wallForces.dat sedimentFront/0/front.dat load/0/forces.dat; do
        [ "$(grep -vc '^#' "$o/Hs0.071/postProcessing/$f" 2>/dev/null)" -ge 1 ] \
            && pass "obstacleSediment_output_${f%%/*}" \
            || fail "obstacleSediment_output_${f%%/*}" "no rows in postProcessing/$f"
    done
else
    fail obstacleSediment_coupled "$(fatal_of "$o/Hs0.071") $(tail -3 "$o/log.Allrun")"
fi
[ ! -e "/dev/shm/$ch" ] && pass obstacleSediment_channel_removed \
    || fail obstacleSediment_channel_removed "/dev/shm/$ch left"

# ---- bad input -------------------------------------------------------------
o="$TMP/obs3"; cp -r "$TUT" "$o"
out=$(cd "$o" && ./Allrun 0.1 2>&1); rc=$?
[ $rc -ne 0 ] && echo "$out" | grep -q "0 0.071 0.113 0.152" && [ ! -d "$o/Hs0.1" ] \
    && pass obstacleSediment_badHs || fail obstacleSediment_badHs "exit $rc: $out"
exit $((fails > 0))
