#!/bin/bash
# demRestart.sh — a run restarted from a written time (startFrom
# latestTime, contact histories and the adaptive step read back) repeats
# the continuous run to round-off, for both integrators. Case: the
# slidingToRolling tutorial, whose answer depends on the tangential spring
# history; the restart falls in the sliding phase.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TUT="$ROOT/tutorials/demSolid/granularColumnCollapse"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
fails=0
T="$ROOT/bin/dictTool"
for integ in arkode verlet; do
    for kind in continuous restarted; do
        c="$WORK/$integ.$kind"
        cp -r "$TUT" "$c"
        "$T" "$c/system/demSolution" -set "integrator=$integ" >/dev/null
        "$T" "$c/system/controlDict" -set "writeInterval=0.03" >/dev/null
        "$T" "$c/system/controlDict" -set "writeFormat=ascii" >/dev/null
        "$T" "$c/system/particleDict" -set "regions/beads/min=(0.0047 0.0055 0)" >/dev/null
        "$T" "$c/system/particleDict" -set "regions/beads/max=(0.0155 0.0163 0.0108)" >/dev/null
        "$T" "$c/system/particleDict" -new -set "regions/beads/velocity=(0.1 0 0)" \
            -set "regions/beads/omega=(0 0 30)" >/dev/null
        "$T" "$c/system/controlDict" -set "endTime=0.06" >/dev/null
        (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || fails=$((fails+1))
        if [ $kind = restarted ]; then
            "$T" "$c/system/controlDict" -set "endTime=0.03" >/dev/null
            (cd "$c" && "$ROOT/bin/demSolid" > log.demSolid.1 2>&1) || fails=$((fails+1))
            "$T" "$c/system/controlDict" -set "endTime=0.06" >/dev/null
            "$T" "$c/system/controlDict" -set "startFrom=latestTime" >/dev/null
        fi
        (cd "$c" && "$ROOT/bin/demSolid" > log.demSolid 2>&1) || fails=$((fails+1))
    done
    a="$WORK/$integ.continuous/0.06/dem.vtu"
    b="$WORK/$integ.restarted/0.06/dem.vtu"
    if [ ! -f "$a" ] || [ ! -f "$b" ]; then
        echo "FAIL restart $integ: 0.06/dem.vtu missing"; fails=$((fails+1)); continue
    fi
    # compare every number of the two ascii files (positions, velocities,
    # spins) to 1e-12 relative
    diffs=$(paste -d'\n' <(tr -s ' <>"=\n' '\n' < "$a") <(tr -s ' <>"=\n' '\n' < "$b") |
        awk 'NR % 2 { x = $0; next }
             x != $0 { if (x + 0 == x && $0 + 0 == $0) {
                          d = x - $0; s = (x < 0 ? -x : x) + 1e-300
                          if ((d < 0 ? -d : d) > 1e-12 * s && (d < 0 ? -d : d) > 1e-15) n++
                       } else n++ }
             END { print n + 0 }')
    pvd=$(grep -c 'DataSet' "$WORK/$integ.restarted/dem.pvd")
    if [ "$diffs" = 0 ]; then
        echo "PASS restart $integ: restarted run equals the continuous run at t = 0.06 s (1e-12)"
    else
        echo "FAIL restart $integ: $diffs values differ between restarted and continuous runs"
        fails=$((fails+1))
    fi
    if [ "$pvd" = 3 ]; then
        echo "PASS restart $integ: dem.pvd lists 0, 0.03, 0.06 once each"
    else
        echo "FAIL restart $integ: dem.pvd has $pvd data sets, expected 3"; fails=$((fails+1))
    fi
done
exit $((fails > 0))
