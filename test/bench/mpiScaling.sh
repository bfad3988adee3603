#!/usr/bin/env bash
# mpiScaling.sh [DP [ENDTIME [ROUNDS]]] — mpsFluid on one machine: one
# process against MPI ranks (issue 22; not a test: prints a table).
#
# Kleefsman's tank (tutorials/mpsFluid/damBreakObstacle) at spacing DP
# (default 0.04 m: 44 892 particles) from 0 to ENDTIME (default 0.2 s),
# the case as shipped otherwise (PCG with Jacobi; adaptive step), in turn:
#   serial 1t     bin/mpsFluid, 1 OpenMP thread
#   serial 2t     bin/mpsFluid, 2 threads
#   mpi 1x1       bin-hypre/mpsFluid -parallel on 1 rank (the distributed
#                 code path: ghosts, hypre PCG with diagonal scaling)
#   mpi 2x1       2 ranks of 1 thread
#   mpi 4x1       4 ranks of 1 thread (oversubscribed on 2 cores)
# ROUNDS times (default 1), fastest wall time of each kept. Prints wall
# time, speed-up against serial 1t, steps, PPE iterations per step, the
# largest front and force difference against serial 1t, and from the
# distributed runs the migrations and ghosts per rank. Stop other jobs
# first: the load average is printed with the table.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
DP=${1:-0.04}
END=${2:-0.2}
ROUNDS=${3:-1}
MPI_FLUID=$ROOT/bin-hypre/mpsFluid
[ -x "$MPI_FLUID" ] || { echo "build the MPI mpsFluid first: make MPI=1 bin-hypre/mpsFluid" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
B="$TMP/base"
cp -r "$ROOT/tutorials/mpsFluid/damBreakObstacle" "$B"
"$ROOT/bin/dictTool" "$B/system/particleDict" -set "dp=$DP" > /dev/null || exit 1
"$ROOT/bin/dictTool" "$B/system/controlDict" -set "endTime=$END" -set "writeInterval=$END" > /dev/null || exit 1
(cd "$B" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || { echo "genParticles failed" >&2; exit 1; }
echo "# $(date -u '+%F %T UTC'); Kleefsman dp $DP m, 0-$END s, $(nproc) cores; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"

run() {  # label threads ranks(0 = one process) -> sets wall in $TMP/<label>.<round>
    local label=$1 th=$2 np=$3 d="$TMP/$1.$4"
    cp -r "$B" "$d"
    local t0=$(date +%s.%N)
    if [ "$np" = 0 ]; then
        (cd "$d" && OMP_NUM_THREADS=$th "$ROOT/bin/mpsFluid" > log 2>&1)
    else
        (cd "$d" && OMP_NUM_THREADS=$th mpirun -np "$np" "$MPI_FLUID" -parallel > log 2>&1)
    fi || { echo "$label failed: $(grep -A1 FATAL "$d/log" | tail -n 1)" >&2; return 1; }
    echo "$(date +%s.%N) - $t0" | bc > "$d/wall"
}
labels=("serial 1t:1:0" "serial 2t:2:0" "mpi 1x1:1:1" "mpi 2x1:1:2" "mpi 4x1:1:4")
for r in $(seq 1 "$ROUNDS"); do
    for l in "${labels[@]}"; do
        IFS=: read -r name th np <<< "$l"
        run "${name// /_}" "$th" "$np" "$r" || exit 1
    done
done
best() {  # label -> directory of the fastest round
    local b="" bw=""
    for d in "$TMP/$1".*; do
        w=$(cat "$d/wall")
        if [ -z "$bw" ] || awk -v a="$w" -v b="$bw" 'BEGIN { exit !(a < b) }'; then b=$d; bw=$w; fi
    done
    echo "$b"
}
ref=$(best serial_1t)
fro() { tail -n 1 "$1"/postProcessing/waterFront/0/front.dat | awk '{ print $2 }'; }
frc() { tail -n 1 "$1"/postProcessing/load/0/forces.dat | awk '{ print $2 }'; }
echo "| run | wall [s] | speed-up | steps | PPE iterations per step | front at $END s [m] | force x [N] | migrations | ghosts per rank (mean / largest) |"
echo "|---|---|---|---|---|---|---|---|---|"
for l in "${labels[@]}"; do
    IFS=: read -r name th np <<< "$l"
    d=$(best "${name// /_}")
    w=$(cat "$d/wall"); w0=$(cat "$ref/wall")
    steps=$(sed -n 's/^ *steps *\([0-9]*\).*/\1/p' "$d/log")
    it=$(sed -n 's/.*PPE iterations .*(\([0-9.]*\) per step).*/\1/p' "$d/log")
    mig=$(sed -n 's/.* \([0-9]*\) migrations.*/\1/p' "$d/log")
    gh=$(sed -n 's/.*ghosts per rank \([0-9]*\) (mean), \([0-9]*\) (largest.*/\1 \/ \2/p' "$d/log")
    printf '| %s | %.1f | %.2f | %s | %s | %s | %s | %s | %s |\n' "$name" "$w" "$(echo "$w0 / $w" | bc -l)" \
        "$steps" "$it" "$(fro "$d")" "$(frc "$d")" "${mig:--}" "${gh:--}"
done
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg); $(sed -n 's/.*Fluid cloud [^:]*: \([0-9]*\) particles.*/\1/p' "$ref/log") particles"
