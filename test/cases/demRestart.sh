#!/bin/bash
# demRestart.sh — a run restarted from a written time (startFrom
# latestTime, contact histories and the adaptive step read back) repeats
# the continuous run to round-off, for every integrator. Case: a small
# granular column thrown sideways (tutorials/demSolid/granularColumnCollapse,
# histories of a dense pack); for auto also a bead dropped on the floor,
# restarted in its flight after the first bounce (ARKode, Verlet and
# ARKode again before the write, so the restart must decide afresh as the
# continuous run does).
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TUT="$ROOT/tutorials/demSolid/granularColumnCollapse"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
fails=0
T="$ROOT/bin/dictTool"
# column: the granular column; bead: one bead dropped from 5 cm (bounce
# at 0.1 s, in flight at the write at 0.15 s)
setup() {
    local c=$1 integ=$2 kind=$3
    if [ "$kind" = column ]; then
        cp -r "$TUT" "$c"
        "$T" "$c/system/particleDict" -set "regions/beads/min=(0.0047 0.0055 0)" >/dev/null
        "$T" "$c/system/particleDict" -set "regions/beads/max=(0.0155 0.0163 0.0108)" >/dev/null
        "$T" "$c/system/particleDict" -new -set "regions/beads/velocity=(0.1 0 0)" \
            -set "regions/beads/omega=(0 0 30)" >/dev/null
    else
        cp -r "$ROOT/tutorials/demSolid/slidingToRolling" "$c"
        "$T" "$c/system/particleDict" -set "regions/tank/max=(0.08 0.01 0.06)" \
            -set "regions/bead/min=(0.00365 0.00365 0.05)" \
            -set "regions/bead/max=(0.00635 0.00635 0.0527)" \
            -set "regions/bead/velocity=(0 0 0)" > /dev/null
        "$T" "$c/system/controlDict" -set "deltaT=0.01" > /dev/null
    fi
    "$T" "$c/system/demSolution" -set "integrator=$integ" >/dev/null
    "$T" "$c/system/controlDict" -set "writeInterval=$half" >/dev/null
    "$T" "$c/system/controlDict" -set "writeFormat=ascii" >/dev/null
    "$T" "$c/system/controlDict" -set "endTime=$end" >/dev/null
}
for run in column:arkode column:verlet column:auto bead:auto; do
    kind=${run%%:*} integ=${run##*:}
    if [ "$kind" = column ]; then half=0.03 end=0.06; else half=0.15 end=0.3; fi
    for how in continuous restarted; do
        c="$WORK/$kind.$integ.$how"
        setup "$c" "$integ" "$kind"
        (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || fails=$((fails+1))
        if [ $how = restarted ]; then
            "$T" "$c/system/controlDict" -set "endTime=$half" >/dev/null
            (cd "$c" && "$ROOT/bin/demSolid" > log.demSolid.1 2>&1) || fails=$((fails+1))
            "$T" "$c/system/controlDict" -set "endTime=$end" >/dev/null
            "$T" "$c/system/controlDict" -set "startFrom=latestTime" >/dev/null
        fi
        (cd "$c" && "$ROOT/bin/demSolid" > log.demSolid 2>&1) || fails=$((fails+1))
    done
    integ=$kind.$integ
    a="$WORK/$integ.continuous/$end/dem.vtu"
    b="$WORK/$integ.restarted/$end/dem.vtu"
    if [ ! -f "$a" ] || [ ! -f "$b" ]; then
        echo "FAIL restart $integ: $end/dem.vtu missing"; fails=$((fails+1)); continue
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
        echo "PASS restart $integ: restarted run equals the continuous run at t = $end s (1e-12)"
    else
        echo "FAIL restart $integ: $diffs values differ between restarted and continuous runs"
        fails=$((fails+1))
    fi
    if [ "$pvd" = 3 ]; then
        echo "PASS restart $integ: dem.pvd lists 0, $half, $end once each"
    else
        echo "FAIL restart $integ: dem.pvd has $pvd data sets, expected 3"; fails=$((fails+1))
    fi
done
exit $((fails > 0))
