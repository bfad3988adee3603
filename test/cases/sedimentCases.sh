#!/usr/bin/env bash
# sedimentCases.sh — the sediment cases of Xie et al. 2025 §4 (issue 17),
# short runs of tutorials/mpsDem/obstacleSediment (OBS) and
# tutorials/mpsDem/columnSediment (COL):
#   *_clearWater  ./Allrun 0 (no grains, mpsFluid alone) writes the same
#                 fields and the same sensor files, byte for byte, as the
#                 clear-water tutorial it extends (mpsFluid/damBreakObstacle,
#                 mpsFluid/squareColumn) run with the same fixed deltaT:
#                 H_s = 0 is that case
#   *_coupled     the smallest sediment height (OBS 0.071: 5760 grains; COL
#                 0.041: 9760 grains), mpsFluid + demSolid in tandem, Model
#                 B, reaches End in both programs over 5 coupling steps;
#                 dem.vtu holds every grain, on the reservoir floor; the
#                 grains' load on the structure, the sediment front and the
#                 fluid load are written; no channel segment is left
#   *_badHs       ./Allrun with a height the paper does not have is refused
#                 naming the valid ones, and runs nothing
NAME=sedimentCases
. "$(dirname "$0")/lib/tandem.sh"
export MPSDEM_DIR="$ROOT"
short() { # CASE ENDTIME: end early
    "$ROOT/bin/dictTool" "$1/system/controlDict" -set "endTime=$2" > /dev/null; }

# check TAG TUTORIAL CLEARTUTORIAL HS NGRAINS XMAX ZMAX BAD SENSORFILES...
check()
{
    local tag=$1 tut="$ROOT/tutorials/mpsDem/$2" clear="$ROOT/tutorials/mpsFluid/$3"
    local hs=$4 ng=$5 xmax=$6 zmax=$7 bad=$8; shift 8
    local o="$TMP/$tag" c="$TMP/$tag.clear" f diffs=""
    cp -r "$tut" "$o"; short "$o" 0.0025
    cp -r "$clear" "$c"
    "$ROOT/bin/dictTool" "$c/system/controlDict" -set endTime=0.0025 -set adjustTimeStep=no \
        -set deltaT=5e-4 -set writeControl=runTime > /dev/null
    if (cd "$o" && ./Allrun 0 > log.Allrun 2>&1) && (cd "$c" && ./Allrun > log.Allrun 2>&1); then
        for f in 0/fluid.vtu 0.0025/fluid.vtu "$@"; do
            [ -s "$c/$f" ] && cmp -s "$c/$f" "$o/Hs0/$f" || diffs="$diffs $f"
        done
        [ -z "$diffs" ] && pass ${tag}_clearWater || fail ${tag}_clearWater "differ or missing:$diffs"
    else
        fail ${tag}_clearWater "a run failed: $(fatal_of "$o/Hs0") $(fatal_of "$c")"
    fi
    rm -rf "$o" "$c"

    o="$TMP/$tag.coupled"; cp -r "$tut" "$o"; short "$o" 0.0025
    local ch="mpsdem-$tag-test-$$"
    echo "channel $ch;" >> "$o/system/couplingDict"
    sed -i 's/^timeout .*/timeout 120;/' "$o/system/couplingDict"
    if (cd "$o" && timeout 900 ./Allrun $hs > log.Allrun 2>&1) \
       && grep -q '^End' "$o/Hs$hs/log.mpsFluid" && grep -q '^End' "$o/Hs$hs/log.demSolid"; then
        pass ${tag}_coupled
        local n
        n=$("$ROOT/bin/vtuInfo" -dump "$o/Hs$hs/0.0025/dem.vtu" 2>/dev/null \
            | awk -v x=$xmax -v z=$zmax '$1 ~ /^[0-9]/ && $1 > 0 && $1 < x && $3 > 0 && $3 < z { n++ } END { print n + 0 }')
        [ "$n" = "$ng" ] && pass ${tag}_grains \
            || fail ${tag}_grains "$n of $ng grains on the reservoir floor at 0.0025 s"
        for f in solidLoad/0/wallForces.dat sedimentFront/0/front.dat load/0/forces.dat; do
            [ "$(grep -vc '^#' "$o/Hs$hs/postProcessing/$f" 2>/dev/null)" -ge 1 ] \
                && pass "${tag}_output_${f%%/*}" \
                || fail "${tag}_output_${f%%/*}" "no rows in postProcessing/$f"
        done
    else
        fail ${tag}_coupled "$(fatal_of "$o/Hs$hs") $(tail -3 "$o/log.Allrun")"
    fi
    [ ! -e "/dev/shm/$ch" ] && pass ${tag}_channel_removed \
        || fail ${tag}_channel_removed "/dev/shm/$ch left"
    rm -rf "$o"

    o="$TMP/$tag.bad"; cp -r "$tut" "$o"
    local out rc
    out=$(cd "$o" && ./Allrun $bad 2>&1); rc=$?
    [ $rc -ne 0 ] && echo "$out" | grep -q "is not one of the paper's" && [ ! -d "$o/Hs$bad" ] \
        && pass ${tag}_badHs || fail ${tag}_badHs "exit $rc: $out"
    rm -rf "$o"
}

check OBS obstacleSediment damBreakObstacle 0.071 5760 3.22 0.064 0.1 \
    postProcessing/heights/0/waveGauges.dat postProcessing/pressure/0/probes.dat \
    postProcessing/load/0/forces.dat postProcessing/waterFront/0/front.dat
check COL columnSediment squareColumn 0.041 9760 0.4 0.04 0.05 \
    postProcessing/H1/0/waveGauges.dat postProcessing/P1/0/probes.dat \
    postProcessing/velocity/0/probes.dat postProcessing/load/0/forces.dat \
    postProcessing/waterFront/0/front.dat
exit $((fails > 0))
