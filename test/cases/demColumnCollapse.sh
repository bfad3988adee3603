#!/bin/bash
# demColumnCollapse.sh — the granularColumnCollapse tutorial cut to a
# 6 x 6 x 6 block (216 beads) released in air for 0.3 s (quick E2-09):
#   - the block settles (E2-09, per bead): E_k after 0.2 s stays below
#     1e-9 J x 216/7425 (the tutorial's printed dashpot, restitutionConstant;
#     with the default restitution damping the columns ring, see its README);
#   - the floor carries the weight: wallForces on the tank, averaged over
#     the last 0.1 s (every step), equals -N m g within 2 %;
#   - no bead is lost; the front never moves backwards of the block face.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TUT="$ROOT/tutorials/demSolid/granularColumnCollapse"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
T="$ROOT/bin/dictTool"
fails=0
c="$WORK/case"
cp -r "$TUT" "$c"
"$T" "$c/system/particleDict" -set "regions/beads/max=(0.0209 0.0217 0.0189)" > /dev/null
"$T" "$c/system/controlDict" -set "endTime=0.3" > /dev/null
"$T" "$c/system/controlDict" -set "writeInterval=0.3" > /dev/null
"$T" "$c/system/controlDict" -set "functions/walls/writeInterval=1" > /dev/null
if ! (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 \
      && "$ROOT/bin/demSolid" > log.demSolid 2>&1); then
    echo "FAIL columnCollapse: run failed"; tail -5 "$c/log.demSolid"; exit 1
fi
P="$c/postProcessing"
read -r peak late < <(awk '!/^#/ {if ($4 > m) m = $4; if ($1 > 0.2 && $4 > l) l = $4}
    END {printf "%.4g %.4g\n", m, l}' "$P/energy/0/kineticEnergy.dat")
if awk -v p="$peak" -v l="$late" 'BEGIN{exit !(p > 0 && l < 1e-9 * 216 / 7425)}'; then
    echo "PASS columnCollapse settles: E_k peak $peak J, max after 0.2 s $late J (< 2.9e-11 J)"
else
    echo "FAIL columnCollapse settles: E_k peak $peak J, max after 0.25 s $late J"; fails=$((fails+1))
fi
n=$(awk '!/^#/ {n = $5} END {print n}' "$P/energy/0/kineticEnergy.dat")
w=$(awk -v n="$n" 'BEGIN{printf "%.6g", -n * 2500 * 4/3 * 3.141592653589793 * 0.00135^3 * 9.81}')
fz=$(awk '!/^#/ && $1 > 0.2 {s += $4; k++} END {printf "%.6g", s / k}' "$P/walls/0/wallForces.dat")
if awk -v f="$fz" -v w="$w" 'BEGIN{exit !((f/w - 1)^2 < 0.02^2)}'; then
    echo "PASS columnCollapse floor load: F_z = $fz N, -N m g = $w N (2 %)"
else
    echo "FAIL columnCollapse floor load: F_z = $fz N, expected $w N"; fails=$((fails+1))
fi
if [ "$n" = 216 ]; then
    echo "PASS columnCollapse: 216 beads kept"
else
    echo "FAIL columnCollapse: $n beads at the end, 216 expected"; fails=$((fails+1))
fi
front=$(awk '!/^#/ {f = $2} END {print f}' "$P/front/0/front.dat")
if awk -v f="$front" 'BEGIN{exit !(f >= 0.0209 - 1e-6)}'; then
    echo "PASS columnCollapse front at $front m (block face 0.0209 m)"
else
    echo "FAIL columnCollapse front at $front m, behind the block face 0.0209 m"; fails=$((fails+1))
fi
exit $((fails > 0))
