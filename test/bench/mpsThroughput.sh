#!/usr/bin/env bash
# mpsThroughput.sh [STEPS] — throughput of mpsFluid (not a test: prints a
# table). For the 3-D hydrostatic tank and the 3-D Kleefsman dam break at
# about 50k and 200k particles (wall and dummy particles included), all
# operator radii r_e = 2.1 dp, runs STEPS steps (default 30) from the
# tutorial's initial state and prints, from the solver's final statistics:
#   particles, steps, neighbour-list builds,
#   time per particle-step of each phase [us]: neighbours (list update or
#     build, weights), explicit (viscosity, collision, predictor, number
#     density, free surface), assembly (PPE matrix and source), PPE (solve),
#     correction; nonPPE = all but the PPE solve (the issue's target),
#   CG iterations per step, ns per CG iteration per row,
#   the CG's bytes per row-iteration and its share of a bandwidth bound,
#   the process's peak memory [MB] and per particle [kB] (issue 21, item 6).
# The PPE runs Jacobi-PCG (PRECOND=ic0 etc. to change it; the 2-D tutorials
# use IC(0)) because its bytes are known: the fast path of
# src/linsolve/solver_pcg.c streams, per iteration and row,
#   B = 12 nnz/row (CSR values + columns) + 8 x 13 vector streams
#       (row pointer; SpMV p, q; residual r r/w, q, dinv; direction x r/w,
#       p r/w, r, dinv)   [bytes, STREAM counting, no write-allocate].
# Its working set (12 nnz/row + 8 x 7 per row) of a 50k or 200k case is
# tens of MB, which the last-level cache of some machines holds, so two
# bandwidths are measured in the same run (test/bench/mps_stream.c triad):
# DRAM (768 MB of arrays) and a triad of the CG's own working-set size.
#   BW%  = (B / bandwidth at the working-set size) / measured ns per row;
#   DRAM% = the same against the DRAM bandwidth (> 100 % means the CG runs
#          out of cache).
# Threads: OMP_NUM_THREADS (default: all cores). Run on a quiet machine:
# with other jobs on the cores, OpenMP barriers wait for descheduled
# threads and every phase slows down (report the load with the numbers).
# Targets (issue 3): nonPPE <= 1.5 us per particle-step at r_e = 2.1 dp;
# one CG iteration <= 14 ns per row; the PPE >= 60 % of the bound.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
STEPS=${1:-30}
PRECOND=${PRECOND:-jacobi}
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
gcc -O2 -fopenmp "$ROOT/test/bench/mps_stream.c" -o "$TMP/stream" || exit 1
BW=$("$TMP/stream" | awk '{ print $2 }')
echo "# $(date -u '+%F %T UTC'); threads ${OMP_NUM_THREADS:-$(nproc)}; load average $(cut -d' ' -f1-3 /proc/loadavg); PPE pcg/$PRECOND; $STEPS steps"
echo "# DRAM bandwidth (triad, 768 MB): $BW GB/s"
# keys at any indentation (preconditioner sits inside PPE { })
set_key() { sed -i "s|^\(\s*$2\) .*|\1 $3;|" "$1"; }
run() {   # name tutorial dp
    local name=$1 tut=$2 dp=$3 c="$TMP/$1"
    cp -r "$ROOT/tutorials/mpsFluid/$tut" "$c"
    set_key "$c/system/particleDict" dp "$dp"
    set_key "$c/system/mpsSchemes" reNumberDensity 2.1
    set_key "$c/system/mpsSchemes" reGradient 2.1
    set_key "$c/system/mpsSchemes" reLaplacian 2.1
    set_key "$c/system/mpsSolution" preconditioner "$PRECOND"
    local dt; dt=$(awk -v d=$dp 'BEGIN { printf "%.3g", 0.1 * d / 3 }')
    set_key "$c/system/controlDict" adjustTimeStep no
    set_key "$c/system/controlDict" deltaT "$dt"
    set_key "$c/system/controlDict" endTime "$(awk -v d=$dt -v n=$STEPS 'BEGIN { printf "%.6g", d * n }')"
    set_key "$c/system/controlDict" writeInterval 1000
    sed -i '/^functions/,$d' "$c/system/controlDict"
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1) \
        || { echo "$name FAILED (see $c)"; return; }
    grep -q "^Selecting preconditioner $PRECOND " "$c/log.mpsFluid" \
        || { echo "$name: the run did not use preconditioner $PRECOND (see $c)"; return; }
    awk -v name=$name -v bw=$BW -v tmp="$TMP" '
      /steps  / { st = $2; nb_builds = $6; gsub("[)]", "", nb_builds) }
      /particles  / { n = $2 }
      /PPE iterations/ { it = $4; gsub("[(]", "", it) }
      /time per particle-step/ { nb = $6; ex = $8; as = $10; pp = $12; co = $14 }
      /PPE per iteration/ { ns = $4; nz = $8 }
      /peak memory/ { mb = $3; kb = $5; gsub("[(]", "", kb) }
      END { bytes = 12 * nz + 8 * 13
            printf "%s %d %d %s %.3f %.3f %.3f %.3f %.3f %.3f %.1f %.2f %.1f %d %d %.2f\n",
                   name, n, st, nb_builds, nb, ex, as, pp, co, nb + ex + as + co,
                   it, ns, nz, bytes, mb, kb }' "$c/log.mpsFluid" > "$c/row"
    read -r nm n st bl nb ex as pp co non it ns nz bytes mb kb < "$c/row"
    # working set of the CG, matrix + 7 vectors, counted on all particles
    # (the unknowns exclude dummies and the surface: an upper estimate)
    local wsmb; wsmb=$(awk -v m=$n -v nz=$nz 'BEGIN { printf "%.1f", m * (12 * nz + 56) / 1048576 }')
    local bwc; bwc=$("$TMP/stream" "$(awk -v w=$wsmb 'BEGIN { print (w < 0.1 ? 0.1 : w) }')" | awk '{ print $2 }')
    awk -v nm=$nm -v n=$n -v st=$st -v bl=$bl -v nb=$nb -v ex=$ex -v as=$as -v pp=$pp \
        -v co=$co -v non=$non -v it=$it -v ns=$ns -v nz=$nz -v by=$bytes -v ws=$wsmb \
        -v bwc=$bwc -v bw=$BW -v mb=$mb -v kb=$kb 'BEGIN {
        printf "%-16s %7d %3d %3d %6.3f %6.3f %6.3f %7.3f %6.3f %6.3f %6.1f %7.2f %5.1f %5d %6.1f %6.1f %5.0f%% %5.0f%% %5d %5.2f\n",
               nm, n, st, bl, nb, ex, as, pp, co, non, it, ns, nz, by, ws, bwc,
               100 * by / bwc / ns, 100 * by / bw / ns, mb, kb }'
}
printf "%-16s %7s %3s %3s %6s %6s %6s %7s %6s %6s %6s %7s %5s %5s %6s %6s %6s %6s %5s %5s\n" \
    case particles stp bld neigh explic assem PPE corr nonPPE it/stp ns/row nz/row B/row ws_MB ws_GBs BW% DRAM% MB kB/p
echo "# times in us per particle-step; ns/row and B/row per CG iteration; ws = CG working set"
run hydrostatic_50k  hydrostaticTank   0.0033
run hydrostatic_200k hydrostaticTank   0.00195
run kleefsman_50k    damBreakObstacle  0.035
run kleefsman_200k   damBreakObstacle  0.0195
