#!/usr/bin/env bash
# mpiParallel.sh — mpsFluid distributed over MPI ranks (issue 22;
# doc/design.md §8): `mpirun -np N bin-hypre/mpsFluid -parallel`, the MPI
# build that test/Alltest makes (make MPI=1), against bin/mpsFluid in one
# process on the same case. Ranks beyond the 2 cores run oversubscribed.
#
# Tolerances: the one-process run solves the PPE with the case's solver
# (PCG with ic0 or Jacobi), the distributed one with hypre (PCG with
# BoomerAMG or diagonal scaling), both to the relative residual 1e-8, and
# the sums run in another order; the runs then differ by what those
# differences grow to, measured 4e-7 m in 0.1 s (damBreak2D, 4 ranks) and
# 3e-13 m in 0.2 s (Kleefsman dp 0.04, 2 ranks). Bound: 1e-5 m
# (0.2 % of the spacing) and 1 Pa.
#   mpi_same_2d       damBreak2D to 0.1 s with 1, 2 and 4 ranks: every
#                     particle (matched by id) within the bounds of the
#                     one-process run, the surge front and column height
#                     within 1e-5 m at every step
#   mpi_migration     with 4 ranks particles migrated, ghosts were held and
#                     the regions were cut afresh as the water moved
#                     (maxImbalance 1.2 by default); the fluid count stays
#                     200 in every row of the volume function object
#   mpi_restart_n     4 ranks to 0.05 s, then 2 ranks from that state to
#                     0.1 s: within 1e-6 m of the 4-rank run to 0.1 s; a
#                     distributed run writes <t>/fluid.pvtu with one piece
#                     fluid_<rank>.vtu per rank, listed in fluid.pvd
#   mpi_restart_serial  one process (bin/mpsFluid) from the 4 pieces at
#                     0.05 s to 0.1 s: within 1e-6 m of the 2-rank run
#   mpi_same_3d       Kleefsman (dp 0.04, 44 892 particles) to 0.02 s on 2
#                     ranks: within the bounds, force on the box within
#                     1e-4 of the one-process value
#   mpi_rank_killed   a rank killed (SIGKILL) mid-run: mpirun ends within
#                     30 s with a non-zero status (no hang)
#   mpi_runParallel   RunFunctions' runParallel takes the ranks from
#                     system/decomposeParDict (2), logs to log.mpsFluid and
#                     refuses to run again while that log exists
#   mpi_same_shifting damBreak2D with the extrapolated dummy pressure and
#                     shifting xu2009, then lind2012, on 2 ranks to 0.1 s:
#                     within the bounds (measured 2.5e-9 m and 1.0e-9 m)
#   mpi_same_surface  the same case with the extrapolated surface pressure
#                     and `sweep simultaneous` on 1 and 2 ranks: within the
#                     bounds (measured 8.1e-10 m); with the sequential
#                     default the distributed run warns (system/mpsSchemes,
#                     its line) and fits simultaneously
#   mpi_refused       -parallel with the build without MPI, with soil
#                     (constant/soilProperties), with maxImbalance 0.5
#                     (system/decomposeParDict, its line): exit 1, the
#                     message, no time directory
# Coupled (mpsFluid on N ranks beside demSolid, runTandem -np N; the grains
# then feel the fluid through sums over the ranks, so the bounds above hold
# for the grains too: measured 7.7e-9 m and 1.2e-3 Pa for the fluid and
# 6e-8 m for the grains after 0.1 s on 4 ranks, 1.1e-12 m and 2.4e-6 Pa
# in the root case after 0.02 s on 1, 2 and 4 ranks):
#   mpi_coupled_2d    2-D two-phase dam break (21 beads, volume fractions),
#                     Model B on 1, 2 and 4 ranks and Model A on 2, to
#                     0.1 s: fluid by id, grain centres within 1e-5 m, every
#                     function object within 1e-5
#   mpi_coupled_restart  Model B, 4 ranks to 0.05 s, then 2 ranks from
#                     there: within 1e-6 m of the 4-rank run to 0.1 s
#   mpi_coupled_root  the root case (3-D, 25 696 particles, 1 026 grains) to
#                     0.02 s on 1, 2 and 4 ranks against one process, as
#                     above
#   mpi_coupled_peer_killed  demSolid killed (SIGKILL) mid-run: the
#                     2-rank mpsFluid ends within 60 s, non-zero, naming the
#                     peer
NAME=mpiParallel; . "$(dirname "$0")/lib/tandem.sh"
need_bins genParticles mpsFluid demSolid vtuInfo
MPI_FLUID=${MPI_FLUID:-$ROOT/bin-hypre/mpsFluid}
[ -x "$MPI_FLUID" ] || { fail "$NAME" "$MPI_FLUID not built (make MPI=1)"; exit 1; }
command -v mpirun > /dev/null || { fail "$NAME" "mpirun not found"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

# case DIR TUTORIAL ENDTIME: a copy with its particles, ending at ENDTIME
case_copy() {
    cp -r "$ROOT/tutorials/$2" "$1" && (cd "$1" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) \
        && "$ROOT/bin/dictTool" "$1/system/controlDict" -set "endTime=$3" > /dev/null
}
# par DIR N [ARGS]: N ranks in DIR, log.par<N>
par() {
    local d=$1 n=$2; shift 2
    (cd "$d" && timeout 300 mpirun -np "$n" "$MPI_FLUID" -parallel "$@" > "log.par$n" 2>&1)
}
# dump VTU: "id x y z ux uy uz p" sorted by id
dump() {
    "$ROOT/bin/vtuInfo" -dump "$1" | awk '/^# x y z/ { for (k = 1; k <= NF; k++) c[$k] = k - 1; next }
        NF > 5 && ("id" in c) { print $c["id"], $1, $2, $3, $(c["velocity_0"]), $(c["velocity_1"]), $(c["velocity_2"]), $(c["pressure"]) }' | sort -n
}
# differ A B DX DP: empty when every particle of A and B (by id) agrees
# within DX [m] in position and DP [Pa] in pressure; else what differs
differ() {
    local na nb
    na=$(dump "$1" | wc -l); nb=$(dump "$2" | wc -l)
    join <(dump "$1") <(dump "$2") | awk -v na="$na" -v nb="$nb" -v tx="$3" -v tp="$4" '
        { n++; for (k = 2; k <= 4; k++) { e = $k - $(k + 7); e = e < 0 ? -e : e; if (e > dx) dx = e }
          e = $8 - $15; e = e < 0 ? -e : e; if (e > dp) dp = e }
        END { if (na != nb || n != na || na == 0) { printf "particles %d / %d, %d matched", na, nb, n; exit }
              if (!(dx <= tx) || !(dp <= tp)) printf "max |dx| %.3g m, |dp| %.3g Pa", dx, dp }'
}
# series A B TOL: the largest difference of two function-object files
# (same rows), or "rows" when their row counts differ
series() {
    paste "$1" "$2" | awk -v t="$3" '/^#/ { next } { h = NF / 2; for (k = 2; k <= h; k++) { e = $k - $(k + h); e = e < 0 ? -e : e; if (e > m) m = e } n++ }
        END { if (!n) print "no rows"; else if (!(m <= t)) printf "%.3g", m }'
}

# --- damBreak2D: 1, 2, 4 ranks against one process ---------------------------
S="$TMP/serial"
case_copy "$S" mpsFluid/damBreak2D 0.1 || { fail mpi_same_2d "case set-up failed"; exit 1; }
"$ROOT/bin/dictTool" "$S/system/controlDict" -set writeInterval=0.05 > /dev/null
for n in 1 2 4; do cp -r "$S" "$TMP/np$n"; done
(cd "$S" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1) || { fail mpi_same_2d "one-process run failed"; exit 1; }
msg=""
for n in 1 2 4; do
    if ! par "$TMP/np$n" $n; then msg+=" np $n failed: $(grep -A1 FATAL "$TMP/np$n/log.par$n" | tail -n 1);"; continue; fi
    d=$(differ "$S/0.1/fluid.vtu" "$TMP/np$n/0.1/fluid.pvtu" 1e-5 1)
    ls "$TMP/np$n"/0.1/fluid_*.vtu 2> /dev/null | wc -l | grep -qx "$n" || d+=" not $n pieces in 0.1/;"
    grep -q 'file="0.1/fluid.pvtu"' "$TMP/np$n/fluid.pvd" || d+=" 0.1/fluid.pvtu not in fluid.pvd;"
    [ -n "$d" ] && msg+=" np $n: $d;"
    for fo in surge column; do
        f=$(ls "$S"/postProcessing/$fo/0/*.dat)
        d=$(series "$f" "$TMP/np$n/${f#"$S"/}" 1e-5)
        [ -n "$d" ] && msg+=" np $n $fo: $d;"
    done
done
[ -z "$msg" ] && pass mpi_same_2d || fail mpi_same_2d "$msg"

# shifting and the extrapolated dummy pressure (the walls' values first)
SH="$TMP/shifting"
cp -r "$S" "$SH"; rm -rf "$SH"/0.* "$SH"/postProcessing "$SH"/*.pvd "$SH"/log.*
"$ROOT/bin/dictTool" "$SH/system/mpsSchemes" -set dummyPressure=extrapolated > /dev/null
msg=""
for sh in xu2009 lind2012; do
    "$ROOT/bin/dictTool" "$SH/system/mpsSchemes" -set shifting=$sh > /dev/null
    rm -rf "$SH.1" "$SH.2"; cp -r "$SH" "$SH.1"; cp -r "$SH" "$SH.2"
    (cd "$SH.1" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1) && par "$SH.2" 2 \
        || { msg+=" $sh: a run failed: $(grep -h -A1 FATAL "$SH".[12]/log.* | tail -n 1);"; continue; }
    d=$(differ "$SH.1/0.1/fluid.vtu" "$SH.2/0.1/fluid.pvtu" 1e-5 1)
    [ -n "$d" ] && msg+=" $sh: $d;"
done
[ -z "$msg" ] && pass mpi_same_shifting || fail mpi_same_shifting "$msg"

# the extrapolated surface pressure: `sweep simultaneous` on 1 and 2 ranks
# alike; the sequential default runs distributed as simultaneous, warned
"$ROOT/bin/dictTool" "$SH/system/mpsSchemes" -new -set freeSurface/pressure=extrapolated > /dev/null
rm -rf "$SH.1" "$SH.2" "$SH.w"; cp -r "$SH" "$SH.w"
"$ROOT/bin/dictTool" "$SH/system/mpsSchemes" -new -set freeSurface/sweep=simultaneous > /dev/null
cp -r "$SH" "$SH.1"; cp -r "$SH" "$SH.2"
msg=""
if (cd "$SH.1" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1) && par "$SH.2" 2; then
    msg=$(differ "$SH.1/0.1/fluid.vtu" "$SH.2/0.1/fluid.pvtu" 1e-5 1)
else
    msg="a run failed: $(grep -h -A1 FATAL "$SH".[12]/log.* | tail -n 1)"
fi
par "$SH.w" 2 && grep -qE "system/mpsSchemes:[0-9]+:[0-9]+: freeSurface \{ pressure extrapolated; \} runs distributed with .sweep simultaneous" "$SH.w/log.par2" \
    || msg+=" sequential default: no warning or failed: $(grep -A1 FATAL "$SH.w/log.par2" | tail -n 1)"
[ -z "$msg" ] && pass mpi_same_surface || fail mpi_same_surface "$msg"

st=$(grep "distributed " "$TMP/np4/log.par4")
mig=$(echo "$st" | sed -n 's/.* \([0-9]*\) migrations.*/\1/p')
gh=$(echo "$st" | sed -n 's/.*ghosts per rank \([0-9.]*\) (mean).*/\1/p')
cuts=$(echo "$st" | sed -n 's/.*regions cut afresh \([0-9]*\) times.*/\1/p')
nfl=$(awk '!/^#/ && $2 != 200 { bad++ } !/^#/ { n++ } END { print n + 0, bad + 0 }' "$TMP"/np4/postProcessing/volume/0/*.dat)
if [ "${mig:-0}" -gt 0 ] && [ "${cuts:-0}" -gt 0 ] && awk -v g="${gh:-0}" 'BEGIN { exit !(g > 0) }' && [ "${nfl#* }" = 0 ] && [ "${nfl% *}" -ge 3 ]; then
    pass mpi_migration
else
    fail mpi_migration "stats '$st', volume rows/bad '$nfl'"
fi

# --- restart with another number of ranks --------------------------------------
R="$TMP/restart"
cp -r "$S" "$R"; rm -rf "$R"/0.* "$R"/postProcessing "$R"/*.pvd "$R"/log.*
"$ROOT/bin/dictTool" "$R/system/controlDict" -set endTime=0.05 > /dev/null
ok=1
par "$R" 4 || ok=0
"$ROOT/bin/dictTool" "$R/system/controlDict" -set endTime=0.1 -set startFrom=latestTime > /dev/null
[ $ok = 1 ] && { par "$R" 2 || ok=0; }
if [ $ok = 1 ]; then
    d=$(differ "$TMP/np4/0.1/fluid.pvtu" "$R/0.1/fluid.pvtu" 1e-6 0.1)
    [ -z "$d" ] && grep -q "Starting from the latest time, 0.05" "$R/log.par2" && pass mpi_restart_n \
        || fail mpi_restart_n "${d:-no restart from 0.05}"
else
    fail mpi_restart_n "a run failed: $(grep -h -A1 FATAL "$R"/log.par* | tail -n 1)"
fi

# --- one process goes on from the pieces of a distributed run ----------------
Q="$TMP/serial_from_pieces"
cp -r "$R" "$Q"; rm -rf "$Q"/0.1 "$Q"/log.*
(cd "$Q" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1)
d=$(differ "$R/0.1/fluid.pvtu" "$Q/0.1/fluid.vtu" 1e-6 0.1)
[ -f "$Q/0.1/fluid.vtu" ] && [ -z "$d" ] && grep -q "Fluid cloud 0.05/fluid.pvtu" "$Q/log.mpsFluid" \
    && pass mpi_restart_serial || fail mpi_restart_serial "${d:-no restart from 0.05/fluid.pvtu: $(grep -A1 FATAL "$Q/log.mpsFluid" | tail -n 1)}"

# --- 3-D: Kleefsman's tank, coarse ----------------------------------------------
K="$TMP/kleefsman"
case_copy "$K" mpsFluid/damBreakObstacle 0.02 || { fail mpi_same_3d "case set-up failed"; exit 1; }
"$ROOT/bin/dictTool" "$K/system/controlDict" -set writeInterval=0.02 > /dev/null
cp -r "$K" "$K.2"
(cd "$K" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1) && par "$K.2" 2
if [ $? -eq 0 ]; then
    d=$(differ "$K/0.02/fluid.vtu" "$K.2/0.02/fluid.pvtu" 1e-5 1)
    f=$(ls "$K"/postProcessing/load/0/*.dat)
    fd=$(paste "$f" "$K.2/${f#"$K"/}" | awk '!/^#/ { h = NF / 2; for (k = 2; k <= h; k++) { e = $k - $(k + h); e = e < 0 ? -e : e; s = $k < 0 ? -$k : $k; if (e > 1e-4 * (s + 1)) bad++ } n++ }
        END { if (!n || bad) print (n ? bad " values" : "no rows") }')
    [ -z "$d$fd" ] && pass mpi_same_3d || fail mpi_same_3d "$d $fd"
else
    fail mpi_same_3d "a run failed: $(grep -h -A1 FATAL "$K"/log.* "$K.2"/log.* | tail -n 1)"
fi

# --- a rank killed mid-run --------------------------------------------------------
F="$TMP/fault"
cp -r "$K" "$F"; rm -rf "$F"/0.0* "$F"/postProcessing "$F"/*.pvd "$F"/log.*
"$ROOT/bin/dictTool" "$F/system/controlDict" -set endTime=5 > /dev/null
(cd "$F" && timeout 120 mpirun -np 2 "$MPI_FLUID" -parallel > log.par2 2>&1; echo $? > "$F/rc") &
for _ in $(seq 1 120); do grep -q "^Time = " "$F/log.par2" 2>/dev/null && break; sleep 0.5; done
victim=""
for p in $(ps -eo pid,comm | awk '$2 == "mpsFluid" { print $1 }'); do
    [ "$(readlink /proc/$p/cwd)" = "$F" ] && victim=$p
done
if [ -n "$victim" ]; then
    kill -9 "$victim"
    t0=$(date +%s)
    while [ ! -s "$F/rc" ] && [ $(( $(date +%s) - t0 )) -lt 30 ]; do sleep 0.5; done
    rc=$(cat "$F/rc" 2>/dev/null)
    [ -n "$rc" ] && [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] && pass mpi_rank_killed \
        || fail mpi_rank_killed "mpirun status '${rc:-none after 30 s}'"
else
    fail mpi_rank_killed "no rank of the run found: $(tail -n 3 "$F/log.par2")"
fi
wait

# --- runParallel (RunFunctions, as OpenFOAM's) ------------------------------------
RP="$TMP/runParallel"
cp -r "$S" "$RP"; rm -rf "$RP"/0.* "$RP"/postProcessing "$RP"/*.pvd "$RP"/log.*
"$ROOT/bin/dictTool" "$RP/system/controlDict" -set endTime=0.01 -set writeInterval=0.01 > /dev/null
printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\n' \
    > "$RP/system/decomposeParDict"
out=$(cd "$RP" && . "$ROOT/bin/tools/RunFunctions" && runParallel mpsFluid && runParallel mpsFluid 2>&1); rc=$?
[ $rc -eq 0 ] && echo "$out" | grep -q "using 2 processes" && echo "$out" | grep -q "already run" \
    && grep -q "Distributed over 2 ranks" "$RP/log.mpsFluid" && [ -f "$RP/0.01/fluid.pvtu" ] \
    && pass mpi_runParallel || fail mpi_runParallel "rc $rc: $(echo "$out" | tail -n 2 | tr '\n' ' ')"

# --- refused ----------------------------------------------------------------------
c="$TMP/refused"
cp -r "$S" "$c"; rm -rf "$c"/0.* "$c"/postProcessing "$c"/*.pvd "$c"/log.*
out=$(cd "$c" && "$ROOT/bin/mpsFluid" -parallel 2>&1); rc=$?
extra=$(cd "$c" && ls -d [0-9]* | grep -v '^0$')
[ $rc -eq 1 ] && echo "$out" | grep -q "built without MPI.*make MPI=1" && [ -z "$extra" ] \
    && pass mpi_refused_serial_build || fail mpi_refused_serial_build "rc $rc: $(echo "$out" | grep -A1 FATAL | tail -n 1)"
SO="$TMP/soil"
case_copy "$SO" mpsFluid/soilLayerStill 0.01 || fail mpi_refused_soil "case set-up failed"
par "$SO" 2; out=$(cat "$SO/log.par2")
extra=$(cd "$SO" && ls -d [0-9]* | grep -v '^0$')
echo "$out" | grep -q "constant/soilProperties: a case with soil particles does not run distributed" && [ -z "$extra" ] \
    && ! grep -q "^End" "$SO/log.par2" && pass mpi_refused_soil \
    || fail mpi_refused_soil "$(echo "$out" | grep -A1 FATAL | tail -n 1) time dirs '$extra'"
printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmaxImbalance 0.5;\n' \
    > "$c/system/decomposeParDict"
rm -f "$c/log.par2"; par "$c" 2; out=$(cat "$c/log.par2")
extra=$(cd "$c" && ls -d [0-9]* | grep -v '^0$')
echo "$out" | grep -qE "decomposeParDict:3:[0-9]+: maxImbalance 0.5: give a factor > 1" && [ -z "$extra" ] \
    && pass mpi_refused_imbalance || fail mpi_refused_imbalance "$(echo "$out" | grep -A1 FATAL | tail -n 1) time dirs '$extra'"
# --- coupled: mpsFluid on N ranks with demSolid (runTandem -np N) -------------
# tandem DIR N: runTandem with mpsFluid on N ranks (0: one process)
tandem() {
    local np=""; [ "$2" != 0 ] && np="-np $2"
    (cd "$1" && OMP_NUM_THREADS=1 timeout 300 bash -c ". '$ROOT/bin/tools/RunFunctions'; runTandem $np mpsFluid demSolid" > log.tandem 2>&1)
}
# grains DEM_A DEM_B TOL: empty when every grain centre agrees within TOL [m]
grains() {
    paste <("$ROOT/bin/vtuInfo" -dump "$1" | awk '!/^#/ && NF >= 3 { print $1, $2, $3 }') \
          <("$ROOT/bin/vtuInfo" -dump "$2" | awk '!/^#/ && NF >= 3 { print $1, $2, $3 }') |
    awk -v t="$3" '{ n++; for (k = 1; k <= 3; k++) { e = $k - $(k + 3); e = e < 0 ? -e : e; if (e > m) m = e } }
        END { if (!n || !(m <= t)) printf "grains: %d, max |dx| %.3g m", n, m }'
}
# same_coupled REF DIR TIME: fluid, grains and every function object of
# DIR against REF at TIME
same_coupled() {
    local fl d
    fl="$2/$3/fluid.pvtu"; [ -f "$fl" ] || fl="$2/$3/fluid.vtu"
    d=$(differ "$1/$3/fluid.vtu" "$fl" 1e-5 1)
    d+=$(grains "$1/$3/dem.vtu" "$2/$3/dem.vtu" 1e-5)
    for f in $(cd "$1" && find postProcessing -name '*.dat'); do
        [ -f "$2/$f" ] || { d+=" no $f;"; continue; }
        r=$(series "$1/$f" "$2/$f" 1e-5); [ -n "$r" ] && d+=" $f: $r;"
    done
    echo "$d"
}
CB="$TMP/coupled_B"
case_dam_break_2d "$CB"
"$ROOT/bin/dictTool" "$CB/system/controlDict" -set endTime=0.1 -set writeInterval=0.05 > /dev/null
sed -i "s/^timeout .*/timeout 30;/" "$CB/system/couplingDict"
(cd "$CB" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || fail mpi_coupled_2d "genParticles failed"
CA="$TMP/coupled_A"
cp -r "$CB" "$CA"
"$ROOT/bin/dictTool" "$CA/system/couplingDict" -set model=A > /dev/null
msg=""
for m in A B; do
    for n in 0 1 2 4; do
        [ $m = A ] && [ $n != 0 ] && [ $n != 2 ] && continue
        c="$TMP/coupled_${m}$n"; cp -r "$TMP/coupled_$m" "$c"
        tandem "$c" $n || { msg+=" $m np $n failed: $(fatal_of "$c");"; continue; }
        [ $n = 0 ] && continue
        d=$(same_coupled "$TMP/coupled_${m}0" "$c" 0.1)
        grep -q "Distributed over $n ranks" "$c/log.mpsFluid" || d+=" not on $n ranks;"
        [ -n "$d" ] && msg+=" model $m np $n: $d;"
    done
done
[ -z "$msg" ] && pass mpi_coupled_2d || fail mpi_coupled_2d "$msg"

# restart of a coupled run on another number of ranks
CR="$TMP/coupled_restart"
cp -r "$CB" "$CR"
"$ROOT/bin/dictTool" "$CR/system/controlDict" -set endTime=0.05 > /dev/null
ok=1
tandem "$CR" 4 || ok=0
"$ROOT/bin/dictTool" "$CR/system/controlDict" -set endTime=0.1 -set startFrom=latestTime > /dev/null
rm -f "$CR"/log.mpsFluid "$CR"/log.demSolid
[ $ok = 1 ] && { tandem "$CR" 2 || ok=0; }
if [ $ok = 1 ]; then
    d=$(differ "$TMP/coupled_B4/0.1/fluid.pvtu" "$CR/0.1/fluid.pvtu" 1e-6 0.1)
    d+=$(grains "$TMP/coupled_B4/0.1/dem.vtu" "$CR/0.1/dem.vtu" 1e-6)
    [ -z "$d" ] && grep -q "Starting from the latest time, 0.05" "$CR/log.mpsFluid" && pass mpi_coupled_restart \
        || fail mpi_coupled_restart "${d:-no restart from 0.05}"
else
    fail mpi_coupled_restart "a run failed: $(fatal_of "$CR")"
fi

# the root case (3-D, Model B, 1026 grains), coarse and short, on 1, 2, 4 ranks
RC="$TMP/root_case"
mkdir -p "$RC" && cp -r "$ROOT"/system "$ROOT"/constant "$RC"/ \
    && "$ROOT/bin/dictTool" "$RC/system/controlDict" -set endTime=0.02 -set writeInterval=0.01 > /dev/null \
    && sed -i "s/^timeout .*/timeout 60;/" "$RC/system/couplingDict" \
    && (cd "$RC" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) || fail mpi_coupled_root "case set-up failed"
msg=""
if tandem "$RC" 0; then
    for n in 1 2 4; do
        cp -r "$RC" "$RC.$n"; rm -rf "$RC.$n"/0.0* "$RC.$n"/postProcessing "$RC.$n"/*.pvd "$RC.$n"/log.*
        tandem "$RC.$n" $n || { msg+=" np $n failed: $(fatal_of "$RC.$n");"; continue; }
        d=$(same_coupled "$RC" "$RC.$n" 0.02)
        [ -n "$d" ] && msg+=" np $n: $d;"
    done
else
    msg="one process failed: $(fatal_of "$RC")"
fi
[ -z "$msg" ] && pass mpi_coupled_root || fail mpi_coupled_root "$msg"

# the peer dies: every rank stops with the channel's message, no hang
CK="$TMP/coupled_kill"
cp -r "$CB" "$CK"
"$ROOT/bin/dictTool" "$CK/system/controlDict" -set endTime=5 > /dev/null
(cd "$CK" && OMP_NUM_THREADS=1 timeout 120 mpirun -np 2 "$MPI_FLUID" -parallel > log.mpsFluid 2>&1; echo $? > "$CK/rc") &
(cd "$CK" && OMP_NUM_THREADS=1 timeout 120 "$ROOT/bin/demSolid" > log.demSolid 2>&1; true) 2> /dev/null &
for _ in $(seq 1 120); do grep -q "^Time = " "$CK/log.mpsFluid" 2>/dev/null && break; sleep 0.5; done
for p in $(ps -eo pid,comm | awk '$2 == "demSolid" { print $1 }'); do
    [ "$(readlink /proc/$p/cwd)" = "$CK" ] && kill -9 "$p"
done
t0=$(date +%s)
while [ ! -s "$CK/rc" ] && [ $(( $(date +%s) - t0 )) -lt 60 ]; do sleep 0.5; done
rc=$(cat "$CK/rc" 2>/dev/null)
[ -n "$rc" ] && [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] && grep -qi "peer\|demSolid" "$CK/log.mpsFluid" \
    && pass mpi_coupled_peer_killed \
    || fail mpi_coupled_peer_killed "mpirun status '${rc:-none after 60 s}': $(grep -A1 FATAL "$CK/log.mpsFluid" | tail -n 1)"
wait
exit $fails
