#!/usr/bin/env bash
# mpsDemTable2.sh — time per fluid step of the coupled two-phase dam break
# (tutorials/mpsDem/twoPhaseDamBreak, Model B) split as in Xie et al. 2025
# Table 2 into the "MPS part" and the "DEM and coupling part", at
# dp = 0.002, 0.0027, 0.003 m, beside the paper's numbers.
#
#   test/bench/mpsDemTable2.sh [STEPS] [DP...]     (default 20 steps, all dp)
#
# Both programs run in tandem, one OpenMP thread each (two cores). From
# log.mpsFluid: the MPS step's own timers (time per particle-step x
# particles), the time in the coupling glue G (pairs, porosity,
# interpolation, reaction) and the time spent waiting for demSolid D (its
# sub-steps, sequential scheme) over N steps: DEM + coupling = (G+D)/N.
# The bed is the paper's: 7425 touching beads (the tutorial's fluid
# particles hold eps dp^3 of water there, grainVolume scale). The first
# steps are the release of the column, not the paper's mid-run steps.
# MPSFLUID / DEMSOLID override the programs (default bin/).
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
MPSFLUID=${MPSFLUID:-$ROOT/bin/mpsFluid}
DEMSOLID=${DEMSOLID:-$ROOT/bin/demSolid}
steps=${1:-20}; shift
dps=("$@"); [ ${#dps[@]} -eq 0 ] && dps=(0.002 0.0027 0.003)
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
export OMP_NUM_THREADS=1
declare -A paper_mps=([0.002]=4.40082 [0.0027]=1.83128 [0.003]=1.29677)
declare -A paper_dem=([0.002]=3.36281 [0.0027]=3.25171 [0.003]=3.24867)
printf "%-8s %9s %7s | %12s %12s %10s | %9s %9s | %8s %8s\n" dp particles grains \
       "MPS [s]" "DEM+cpl [s]" "total [s]" "paper MPS" "paper DEM" "x MPS" "x DEM"
for dp in "${dps[@]}"; do
    c="$TMP/dp$dp"
    cp -r "$ROOT/tutorials/mpsDem/twoPhaseDamBreak" "$c"
    sed -i "s/^dp .*/dp           $dp;/" "$c/system/particleDict"
    sed -i "s/^endTime .*/endTime $(awk -v n="$steps" 'BEGIN { print n * 1e-4 }');/; s/^writeInterval .*/writeInterval 1;/" "$c/system/controlDict"
    echo "channel mpsdem-table2-$$;" >> "$c/system/couplingDict"
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || { echo "dp $dp: genParticles failed"; continue; }
    (cd "$c" && "$MPSFLUID" > log.mpsFluid 2>&1) &
    pf=$!
    (cd "$c" && "$DEMSOLID" > log.demSolid 2>&1)
    wait $pf || { echo "dp $dp: mpsFluid failed: $(grep -A2 FATAL "$c/log.mpsFluid" | tr '\n' ' ')"; continue; }
    np=$(awk '/^MPS particles:/ { print $3 }' "$c/log.genParticles")
    ng=$(awk '/^MPS particles:/ { print $NF }' "$c/log.genParticles")
    awk -v dp="$dp" -v np="$np" -v ng="$ng" -v pm="${paper_mps[$dp]:-0}" -v pd="${paper_dem[$dp]:-0}" '
        /^Coupling: [0-9]+ exchanges/ { n = $2; g = $4; d = $9 }
        /^    particles / { npart = $2 }
        /time per particle-step \[us\]/ { tot = $NF }
        END { m = tot * 1e-6 * npart; c = (g + d) / n
              printf "%-8s %9s %7s | %12.4f %12.4f %10.4f | %9.3f %9.3f | %8.1f %8.1f\n",
                     dp, np, ng, m, c, m + c, pm, pd, (pm > 0 ? pm / m : 0), (pd > 0 ? pd / c : 0) }' "$c/log.mpsFluid"
done
