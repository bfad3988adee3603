#!/bin/bash
# demSlidingToRolling.sh — E2-06 on the slidingToRolling tutorial, with both
# integrators: slip ends at t* = 2 v0/(7 mu g), then v = 5 v0/7 (2 %).
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TUT="$ROOT/tutorials/demSolid/slidingToRolling"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
fails=0
for b in genParticles demSolid dictTool; do
    [ -x "$ROOT/bin/$b" ] || { echo "FAIL demSlidingToRolling: bin/$b missing"; exit 1; }
done
ts=$(awk 'BEGIN{printf "%.6g", 2*0.5/(7*0.2*9.81)}')
vr=$(awk 'BEGIN{printf "%.6g", 5*0.5/7}')
for integ in arkode verlet; do
    c="$WORK/$integ"
    cp -r "$TUT" "$c"
    "$ROOT/bin/dictTool" "$c/system/demSolution" -set "integrator=$integ" >/dev/null
    if ! (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 \
          && "$ROOT/bin/demSolid" > log.demSolid 2>&1); then
        echo "FAIL slidingToRolling $integ: run failed"; fails=$((fails+1)); continue
    fi
    read -r t v < <(awk -v R=0.00135 -v v0=0.5 '!/^#/ {
            s = $5 - R * $9
            if (ts == "" && s < 1e-3 * v0 && n) ts = t0 + ($1 - t0) * (s0 - 1e-3*v0) / (s0 - s)
            t0 = $1; s0 = s; n++; v = $5 }
        END {printf "%.6g %.6g\n", ts, v}' "$c/postProcessing/bead/0/grainState.dat")
    if awk -v x="$t" -v r="$ts" 'BEGIN{exit !(x != "" && (x/r-1)^2 < 0.02^2)}'; then
        echo "PASS slidingToRolling $integ: t* = $t s (analytic $ts, 2 %)"
    else
        echo "FAIL slidingToRolling $integ: t* = $t s, analytic $ts"; fails=$((fails+1))
    fi
    if awk -v x="$v" -v r="$vr" 'BEGIN{exit !((x/r-1)^2 < 0.02^2)}'; then
        echo "PASS slidingToRolling $integ: v = $v m/s (analytic $vr, 2 %)"
    else
        echo "FAIL slidingToRolling $integ: v = $v m/s, analytic $vr"; fails=$((fails+1))
    fi
done
exit $((fails > 0))
