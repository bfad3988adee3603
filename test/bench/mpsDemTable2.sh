#!/usr/bin/env bash
# mpsDemTable2.sh — time per fluid step of the coupled two-phase dam break
# (tutorials/mpsDem/twoPhaseDamBreak, Model B) split as in Xie et al. 2025
# Table 2 into the "MPS part" and the "DEM and coupling part", at
# dp = 0.002, 0.0027, 0.003 m, beside the paper's numbers.
#
#   test/bench/mpsDemTable2.sh [STEPS] [DP...]     (default 20 steps, all dp)
#   FROM=auto test/bench/mpsDemTable2.sh 20        (mid-run, from 0.1 s)
#
# Both programs run in tandem, THREADS OpenMP threads each (default 2: in
# the sequential scheme they take turns, so each has the two cores while it
# computes; the waiting side sleeps on a futex). PPE=symmetric runs the
# PPE as porousLaplacian symmetric + pcg (doc/theory.md A.4's SPD variant)
# instead of the tutorial's 1/eps_j weights + bicgstab. From
# log.mpsFluid: the MPS step's own timers (time per particle-step x
# particles), the time in the coupling glue G (pairs, porosity,
# interpolation, reaction) and the time spent waiting for demSolid D (its
# sub-steps, sequential scheme) over N steps: DEM + coupling = (G+D)/N.
# The bed is the paper's: 7425 touching beads (the tutorial's fluid
# particles hold eps dp^3 of water there, grainVolume scale). The first
# steps are the release of the column, not the paper's mid-run steps
# (FROM= below measures mid-run).
# MPSFLUID / DEMSOLID override the programs (default bin/).
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
MPSFLUID=${MPSFLUID:-$ROOT/bin/mpsFluid}
DEMSOLID=${DEMSOLID:-$ROOT/bin/demSolid}
steps=${1:-20}; shift
dps=("$@"); [ ${#dps[@]} -eq 0 ] && dps=(0.002 0.0027 0.003)
TMP="$(mktemp -d)"
# KEEP=1 keeps the cases and their logs (the path is printed)
if [ -n "${KEEP:-}" ]; then echo "# cases in $TMP"; else trap 'rm -rf "$TMP"' EXIT; fi
export OMP_NUM_THREADS=${THREADS:-2}
PPE=${PPE:-neighbour}
# SOLVER=NAME replaces the PPE solver of system/mpsSolution (e.g. gmres)
SOLVER=${SOLVER:-}
# FROM=DIR: steps from the FROM_TIME (default 0.1 s) state of finished
# runs DIR/modelB-dp<dp> (e.g. a copy of the tutorial after
# ./Allrun B 0.002 B 0.0027 B 0.003) instead of the release; FROM=auto
# makes those states first (the tutorial's ./Allrun to FROM_TIME, one
# thread per program, untimed: 21 min for the three dp at 0.1 s; with
# KEEP=1 they stay for another FROM=)
FROM=${FROM:-}
FROM_TIME=${FROM_TIME:-0.1}
# RE=R sets every MPS operator's r_e to R dp (reNumberDensity, reGradient,
# reLaplacian; the paper states 4.1 for all, doc/theory.md A0-02) in the
# timed runs; a mid-run state is the tutorial's radii's all the same
RE=${RE:-}
# REPEAT=N runs each case N times and keeps the fastest MPS and DEM parts
# (a shared or virtual machine's timings vary by 10-20 % run to run)
REPEAT=${REPEAT:-1}
if [ "$FROM" = auto ]; then
    FROM="$TMP/prep"
    cp -r "$ROOT/tutorials/mpsDem/twoPhaseDamBreak" "$FROM"
    (cd "$FROM" && ./Allclean > /dev/null 2>&1)
    sed -i "s/^endTime .*/endTime $FROM_TIME;/; s/^writeInterval .*/writeInterval $FROM_TIME;/" "$FROM/system/controlDict"
    args=(); for dp in "${dps[@]}"; do args+=(B "$dp"); done
    echo "# preparing the $FROM_TIME s states in $FROM (./Allrun ${args[*]})" >&2
    MPSDEM_DIR="$ROOT" "$FROM/Allrun" "${args[@]}" > "$FROM/log.Allrun" 2>&1 \
        || { echo "preparing the states failed: $(tail -3 "$FROM/log.Allrun" | tr '\n' ' ')"; exit 1; }
fi
echo "# $(date -u '+%F %T UTC'); $OMP_NUM_THREADS threads per program; load average $(cut -d' ' -f1-3 /proc/loadavg); PPE weights $PPE${SOLVER:+, solver $SOLVER}; r_e ${RE:-of the tutorial}; $steps steps${FROM:+ from $FROM_TIME s of $FROM}; fastest of $REPEAT"
declare -A paper_mps=([0.002]=4.40082 [0.0027]=1.83128 [0.003]=1.29677)
declare -A paper_dem=([0.002]=3.36281 [0.0027]=3.25171 [0.003]=3.24867)
printf "%-8s %9s %7s %7s | %12s %12s %10s | %9s %9s | %8s %8s\n" dp particles fluid grains \
       "MPS [s]" "DEM+cpl [s]" "total [s]" "paper MPS" "paper DEM" "x MPS" "x DEM"
for dp in "${dps[@]}"; do
    c="$TMP/dp$dp"
    if [ -n "$FROM" ]; then   # mid-run: restart from $FROM/modelB-dp<dp>/<FROM_TIME>
        src="$FROM/modelB-dp$dp"
        [ -d "$src/$FROM_TIME" ] || { echo "dp $dp: no $src/$FROM_TIME"; continue; }
        mkdir -p "$c" && cp -r "$src/constant" "$src/system" "$src/$FROM_TIME" "$c/"
        cp "$src/log.genParticles" "$c/"
        sed -i "s/^startFrom .*/startFrom latestTime;/; s/^endTime .*/endTime $(awk -v t="$FROM_TIME" -v n="$steps" 'BEGIN { print t + n * 1e-4 }');/; s/^writeInterval .*/writeInterval 1;/" "$c/system/controlDict"
        # the pressure solver is not part of the state: the tutorial's own
        cp "$ROOT/tutorials/mpsDem/twoPhaseDamBreak/system/mpsSolution" "$c/system/"
    else
        cp -r "$ROOT/tutorials/mpsDem/twoPhaseDamBreak" "$c"
        sed -i "s/^dp .*/dp           $dp;/" "$c/system/particleDict"
        sed -i "s/^endTime .*/endTime $(awk -v n="$steps" 'BEGIN { print n * 1e-4 }');/; s/^writeInterval .*/writeInterval 1;/" "$c/system/controlDict"
    fi
    if [ -n "$RE" ]; then
        for k in reNumberDensity reGradient reLaplacian; do
            sed -i "s/^$k .*/$k $RE;/" "$c/system/mpsSchemes"
        done
        # the release generates its particles: dummies for the radius
        sed -i "s/^kernelRadius .*/kernelRadius $RE;/" "$c/system/particleDict"
    fi
    echo "channel mpsdem-table2-$$;" >> "$c/system/couplingDict"
    if [ "$PPE" = symmetric ]; then
        sed -i '/^porousLaplacian /d' "$c/system/mpsSchemes"
        echo "porousLaplacian symmetric;" >> "$c/system/mpsSchemes"
        sed -i 's|^\(\s*solver\) .*|\1 pcg;|' "$c/system/mpsSolution"
    fi
    [ -n "$SOLVER" ] && sed -i "s|^\(\s*solver\) .*|\1 $SOLVER;|" "$c/system/mpsSolution"
    [ -n "$FROM" ] || (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || { echo "dp $dp: genParticles failed"; continue; }
    np=$(awk '/^MPS particles:/ { print $3 }' "$c/log.genParticles")
    ng=$(awk '/^MPS particles:/ { print $NF }' "$c/log.genParticles")
    # fluid particles: the "fluid" column of genParticles' region table
    nf=$(awk '/ patch +region +type/ { t = 1; next } t && $1 ~ /^[0-9]+$/ { f += $5 } t && $1 !~ /^[0-9]+$/ { t = 0 } END { print f }' "$c/log.genParticles")
    best="" keep=0
    [ -n "$FROM" ] && keep=$FROM_TIME
    for rep in $(seq "$REPEAT"); do
        # a repeat starts from the same state: drop what the last one wrote
        find "$c" -mindepth 1 -maxdepth 1 -type d -name '[0-9]*' ! -name "$keep" -exec rm -rf {} +
        rm -rf "$c/postProcessing"
        (cd "$c" && "$MPSFLUID" > log.mpsFluid 2>&1) &
        pf=$!
        (cd "$c" && "$DEMSOLID" > log.demSolid 2>&1)
        wait $pf || { echo "dp $dp: mpsFluid failed: $(grep -A2 FATAL "$c/log.mpsFluid" | tr '\n' ' ')"; continue 2; }
        # MPS part: the step's own timers (per particle-step x particles);
        # DEM + coupling: (glue + waiting for demSolid) per exchange
        run=$(awk '/^Coupling: [0-9]+ exchanges/ { n = $2; g = $7; d = $12 }
                   /^    particles / { npart = $2 }
                   /^    PPE iterations/ { it = $(NF - 2); gsub(/[(]/, "", it) }
                   /time per particle-step \[us\]/ { tot = $NF; $1 = $2 = $3 = $4 = ""; brk = $0 }
                   END { printf "%.4f %.4f %s |%s", tot * 1e-6 * npart, (g + d) / n, it, brk }' "$c/log.mpsFluid")
        echo "# dp $dp run $rep: MPS, DEM+cpl [s/step], PPE it/step | [us/particle-step]: $run" >&2
        best=$(echo "$run" | awk -v b="$best" 'BEGIN { split(b, x, " ") } { m = $1; d = $2; if (b != "" && x[1] < m) m = x[1]; if (b != "" && x[2] < d) d = x[2]; print m, d }')
    done
    echo "$best" | awk -v dp="$dp" -v np="$np" -v nf="$nf" -v ng="$ng" -v pm="${paper_mps[$dp]:-0}" -v pd="${paper_dem[$dp]:-0}" '
        { m = $1; c = $2
          printf "%-8s %9s %7s %7s | %12.4f %12.4f %10.4f | %9.3f %9.3f | %8.1f %8.1f\n",
                 dp, np, nf, ng, m, c, m + c, pm, pd, (pm > 0 ? pm / m : 0), (pd > 0 ? pd / c : 0) }'
done | tee "$TMP/table"
# E1-24 (doc/theory.md): MPS time per step ~ fluid particle count, DEM time
# independent of dp, each within 25 %, against the coarsest row
awk '$1 ~ /^[0-9.]+$/ { n++; dp[n] = $1; np[n] = $2; nf[n] = $3; m[n] = $6; c[n] = $7 }
     END { if (n < 2) exit
           r = 1; for (i = 2; i <= n; i++) if (dp[i] > dp[r]) r = i
           print "E1-24, against dp " dp[r] ": (MPS time ratio)/(fluid count ratio) - 1, the same against all particles, DEM+coupling time ratio - 1"
           for (i = 1; i <= n; i++) if (i != r)
               printf "  dp %-7s %+6.1f %%   %+6.1f %%   %+6.1f %%\n", dp[i],
                      100 * ((m[i] / m[r]) / (nf[i] / nf[r]) - 1),
                      100 * ((m[i] / m[r]) / (np[i] / np[r]) - 1), 100 * (c[i] / c[r] - 1) }' "$TMP/table"
