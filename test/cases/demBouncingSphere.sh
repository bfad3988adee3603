#!/bin/bash
# demBouncingSphere.sh — the bouncingSphere tutorial in quick variants
# (doc/theory.md E.2):
#   E2-04 restitution (damping restitution, the default), wall and
#         head-on: e = 0.9 at 0.1, 0.5 and 1 m/s, and e = 0.1, 0.3, 0.5 at
#         1 m/s; linear and hertz within 0.5 %
#   E2-02 hertz, e = 1, 0.5 m/s head-on: contact time 1.287e-4 s (3 %) and
#         maximum overlap 2.185e-5 m (2 %)
#   E2-03 same run: kinetic energy conserved to 1e-5
# Prints PASS/FAIL lines; exits non-zero if any check failed.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TUT="$ROOT/tutorials/demSolid/bouncingSphere"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }

for b in genParticles demSolid dictTool; do
    [ -x "$ROOT/bin/$b" ] || { echo "FAIL demBouncingSphere: bin/$b missing (make apps)"; exit 1; }
done

# run NAME NORMAL E V DELTAT : copy, edit, run; echo the case directory
run() {
    local c="$WORK/$1"
    cp -r "$TUT" "$c"
    "$ROOT/bin/dictTool" "$c/constant/demProperties" -set "contact/normal=$2" >/dev/null
    "$ROOT/bin/dictTool" "$c/constant/demProperties" -set "e=$3" >/dev/null
    local h; h=$(awk -v v="$4" 'BEGIN{printf "%.9g", v/2}')
    "$ROOT/bin/dictTool" "$c/system/particleDict" -set "regions/drop/velocity=(0 0 -$4)" >/dev/null
    "$ROOT/bin/dictTool" "$c/system/particleDict" -set "regions/left/velocity=($h 0 0)" >/dev/null
    "$ROOT/bin/dictTool" "$c/system/particleDict" -set "regions/right/velocity=(-$h 0 0)" >/dev/null
    local tend; tend=$(awk -v v="$4" 'BEGIN{printf "%.6g", 0.0012/v + 3e-4}')
    "$ROOT/bin/dictTool" "$c/system/controlDict" -set "endTime=$tend" >/dev/null
    "$ROOT/bin/dictTool" "$c/system/controlDict" -set "deltaT=$5" >/dev/null
    "$ROOT/bin/dictTool" "$c/system/controlDict" -set "writeInterval=$tend" >/dev/null
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 \
        && "$ROOT/bin/demSolid" > log.demSolid 2>&1) || return 1
    grep -q '^End' "$c/log.demSolid"
}

# final restitution coefficients "e_wall e_pair" from the grain probe
restitution() {
    tail -n 1 "$1/postProcessing/beads/0/grainState.dat" | awk -v v="$2" \
        '{printf "%.6f %.6f\n", $7 / v, ($23 - $14) / v}'
}

tol=0.005
for law in linear hertz; do
    for ev in "0.9 0.1" "0.9 0.5" "0.9 1" "0.5 1" "0.3 1" "0.1 1"; do
        set -- $ev; e0=$1; v=$2
        name="restitution_${law}_e${e0}_v$v"
        if ! run "$name" $law $e0 $v 1e-5; then
            fail "$name" "run failed (see log)"; continue
        fi
        read -r ew ep < <(restitution "$WORK/$name" $v)
        for pair in "wall $ew" "headOn $ep"; do
            set -- $pair
            if awk -v e="$2" -v e0="$e0" -v t="$tol" 'BEGIN{exit !(e > 0 && (e/e0-1)^2 < t*t)}'; then
                pass "$name $1: e = $2 ($e0 +- $(awk -v t=$tol 'BEGIN{print 100*t}') %)"
            else
                fail "$name $1" "e = $2, expected $e0 +- $tol relative"
            fi
        done
    done
done

# E2-02 / E2-03: hertz, e = 1, 0.5 m/s, probes every 1e-6 s
name=hertz_elastic
if run $name hertz 1 0.5 1e-6; then
    c="$WORK/$name/postProcessing/contacts/0/contacts.dat"
    # pair-contact duration: rows with a grain-grain contact x 1e-6 s;
    # max overlap over those rows (the wall impact is 1 ms earlier)
    read -r tc dmax < <(awk '!/^#/ && $2 > 0 {n++; if ($4 > m) m = $4}
        END {printf "%.6g %.6g\n", n * 1e-6, m}' "$c")
    awk -v x="$tc" 'BEGIN{exit !((x/1.287e-4-1)^2 < 0.03^2)}' \
        && pass "hertz contact time $tc s (1.287e-4 +- 3 %)" \
        || fail "hertz contact time" "$tc s, expected 1.287e-4 +- 3 %"
    awk -v x="$dmax" 'BEGIN{exit !((x/2.185e-5-1)^2 < 0.02^2)}' \
        && pass "hertz max overlap $dmax m (2.185e-5 +- 2 %)" \
        || fail "hertz max overlap" "$dmax m, expected 2.185e-5 +- 2 %"
    k="$WORK/$name/postProcessing/energy/0/kineticEnergy.dat"
    rel=$(awk '!/^#/ {if (!n++) e0 = $4; e1 = $4} END {printf "%.3g", (e1-e0)/e0}' "$k")
    awk -v x="$rel" 'BEGIN{exit !(x*x < 1e-10)}' \
        && pass "hertz e = 1 energy conserved: relative change $rel (< 1e-5)" \
        || fail "hertz e = 1 energy" "relative change $rel, expected < 1e-5"
else
    fail $name "run failed"
fi
exit $((fails > 0))
