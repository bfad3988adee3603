#!/usr/bin/env bash
# mpiCoupled.sh [DP [ENDTIME [NP...]]] — a coupled case with mpsFluid on
# MPI ranks beside demSolid, against one process (issue 22; not a test:
# prints a table).
#
# The seed paper's two-phase dam break (tutorials/mpsDem/twoPhaseDamBreak,
# 7 425 beads) at fluid spacing DP (default 0.0027 m: 94 083 particles)
# from 0 to ENDTIME (default 0.02 s, 200 coupled steps), one thread per
# program as the tutorial runs it: first one process (runTandem mpsFluid
# demSolid), then for each NP (default 2) mpsFluid on NP ranks (runTandem
# -np NP). Every mpsFluid rank and demSolid are processes of their own, so
# NP ranks beside demSolid load NP + 1 processes on the machine's cores.
# Prints the wall time of each run, the time mpsFluid spent in the
# coupling's glue (rank 0's), and the largest difference against one
# process: fluid particles by id (position, pressure), beads by index.
# Stop other jobs first: the load average is printed with the table.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
DP=${1:-0.0027}
END=${2:-0.02}
shift 2 2> /dev/null
NPS=("$@")
[ ${#NPS[@]} -eq 0 ] && NPS=(2)
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
B="$TMP/base"
mkdir -p "$B"
cp -r "$ROOT"/tutorials/mpsDem/twoPhaseDamBreak/{0,constant,system} "$B"/
"$ROOT/bin/dictTool" "$B/system/particleDict" -set "dp=$DP" > /dev/null || exit 1
"$ROOT/bin/dictTool" "$B/system/controlDict" -set "endTime=$END" -set "writeInterval=$END" > /dev/null || exit 1
(cd "$B" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || { echo "genParticles failed" >&2; exit 1; }
n=$(sed -n 's/^MPS particles: \([0-9]*\).*grains: \([0-9]*\).*/\1 particles, \2 beads/p' "$B/log.genParticles")
echo "# $(date -u '+%F %T UTC'); twoPhaseDamBreak dp $DP m ($n), 0-$END s, $(nproc) cores; load average before: $(cut -d' ' -f1-3 /proc/loadavg)"

run() {  # NP (0: one process) -> the case directory
    local d="$TMP/np$1" np=""
    cp -r "$B" "$d"
    [ "$1" != 0 ] && np="-np $1"
    local t0=$(date +%s.%N)
    (cd "$d" && OMP_NUM_THREADS=1 bash -c ". '$ROOT/bin/tools/RunFunctions'; runTandem $np mpsFluid demSolid" > log.tandem 2>&1) \
        || { echo "np $1 failed: $(grep -h -A1 FATAL "$d"/log.* | tail -n 1)" >&2; return 1; }
    echo "$(date +%s.%N) - $t0" | bc > "$d/wall"
}
dump() {  # fluid cloud -> "id x y z p" sorted by id
    "$ROOT/bin/vtuInfo" -dump "$1" | awk '/^# x y z/ { for (k = 1; k <= NF; k++) c[$k] = k - 1; next }
        NF > 5 && ("id" in c) { print $c["id"], $1, $2, $3, $(c["pressure"]) }' | sort -n
}
beads() { "$ROOT/bin/vtuInfo" -dump "$1" | awk '/^# x y z/ { p = 1; next } p && NF >= 3 { print $1, $2, $3 }'; }
run 0 || exit 1
for np in "${NPS[@]}"; do run "$np" || exit 1; done
printf '%-28s %10s %10s %14s %14s %14s\n' run "wall [s]" "glue [s]" "fluid |dx| [m]" "fluid |dp| [Pa]" "beads |dx| [m]"
for np in 0 "${NPS[@]}"; do
    d="$TMP/np$np"
    label="one process"; [ "$np" != 0 ] && label="$np ranks + demSolid"
    glue=$(sed -n 's/.*, \([0-9.e+-]*\) s in the glue.*/\1/p' "$d/log.mpsFluid")
    if [ "$np" = 0 ]; then dx=-; dpr=-; bx=-; else
        fl="$d/$END/fluid.pvtu"; [ -f "$fl" ] || fl="$d/$END/fluid.vtu"
        read -r dx dpr < <(join <(dump "$TMP/np0/$END/fluid.vtu") <(dump "$fl") | awk '
            { for (k = 2; k <= 4; k++) { e = $k - $(k + 4); e = e < 0 ? -e : e; if (e > x) x = e }
              e = $5 - $9; e = e < 0 ? -e : e; if (e > p) p = e } END { printf "%.2g %.2g\n", x, p }')
        bx=$(paste <(beads "$TMP/np0/$END/dem.vtu") <(beads "$d/$END/dem.vtu") | awk '
            { for (k = 1; k <= 3; k++) { e = $k - $(k + 3); e = e < 0 ? -e : e; if (e > m) m = e } } END { printf "%.2g", m }')
    fi
    printf '%-28s %10.1f %10s %14s %14s %14s\n' "$label" "$(cat "$d/wall")" "$glue" "$dx" "$dpr" "$bx"
done
