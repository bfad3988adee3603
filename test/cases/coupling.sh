#!/usr/bin/env bash
# coupling.sh — the coupling channel between two real programs (the test
# tool bin/couplingPeer standing in for mpsFluid and demSolid), and
# runTandem. Peer kills at random moments are in couplingKill.sh.
#
#   round trips with checked data and checksums over 10^5 frames
#   frames of 10^6 grains; capacity growth from 10 to ~4x10^5 grains
#   both start orders; handshake mismatch; stale segment (creator killed;
#   whole pair killed); second pair refused
#   runTandem: success, one program failing early, SIGINT of the tandem
# Each check: no segment left in /dev/shm.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
PEER="$ROOT/bin/couplingPeer"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
fails=0

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }

[ -x "$PEER" ] || { fail coupling "bin/couplingPeer not built"; exit 1; }

newcase()   # a fresh case directory in $c
{
    ncase=$((ncase + 1))
    c="$TMP/case$ncase"
    mkdir -p "$c"
}
ncase=0

segname()   # default channel file of a case directory
{
    local n
    n=$(cd "$1" && "$PEER" -side fluid -printName 2>/dev/null)
    echo "/dev/shm$n"
}

no_segment()   # case: true when nothing of its channel is in /dev/shm
{
    local s
    s=$(segname "$1")
    ! ls "$s" "$s".init.* > /dev/null 2>&1
}

# pair CASE "FLUID ARGS" "SOLID ARGS": run both, sets rf and rs
pair()
{
    local c="$1"
    "$PEER" -side fluid -case "$c" $2 > "$c/log.fluid" 2>&1 &
    local pf=$!
    "$PEER" -side solid -case "$c" $3 > "$c/log.solid" 2>&1
    rs=$?
    wait $pf
    rf=$?
}

# ---- data integrity -----------------------------------------------------------
newcase
t0=$EPOCHREALTIME
pair "$c" "-frames 100000 -grains 8 -quiet" "-frames 100000 -grains 8 -quiet"
t1=$EPOCHREALTIME
if [ $rf -eq 0 ] && [ $rs -eq 0 ] && grep -q "End: 100000 coupling steps" "$c/log.fluid" \
   && grep -q "End: 100000 coupling steps" "$c/log.solid" && no_segment "$c"; then
    pass "coupling 1e5 round trips checked ($(echo "$t1 - $t0" | bc) s)"
else
    fail "coupling 1e5 round trips" "exit $rf/$rs; $(tail -n 3 "$c/log.solid")"
fi

newcase
pair "$c" "-frames 3 -grains 1000000 -gradP -quiet" "-frames 3 -grains 1000000 -gradP -quiet"
if [ $rf -eq 0 ] && [ $rs -eq 0 ] && no_segment "$c"; then
    pass "coupling frames of 1e6 grains (Model A fields)"
else
    fail "coupling frames of 1e6 grains" "exit $rf/$rs; $(tail -n 3 "$c/log.solid")"
fi

newcase
pair "$c" "-frames 20 -quiet" "-frames 20 -grains 10 -grow 20000 -quiet"
if [ $rf -eq 0 ] && [ $rs -eq 0 ] && no_segment "$c"; then
    pass "coupling capacity growth 10 -> 380010 grains without restart"
else
    fail "coupling capacity growth" "exit $rf/$rs; $(tail -n 3 "$c/log.solid")"
fi

# ---- start orders --------------------------------------------------------------
for first in fluid solid; do
    newcase
    other=solid; [ $first = solid ] && other=fluid
    "$PEER" -side $first -case "$c" -frames 50 > "$c/log.$first" 2>&1 &
    p1=$!
    sleep 0.3
    "$PEER" -side $other -case "$c" -frames 50 > "$c/log.$other" 2>&1
    r2=$?
    wait $p1
    r1=$?
    if [ $r1 -eq 0 ] && [ $r2 -eq 0 ] && no_segment "$c"; then
        pass "coupling start order: $first first"
    else
        fail "coupling start order: $first first" "exit $r1/$r2"
    fi
done

# ---- handshake mismatch ---------------------------------------------------------
newcase
pair "$c" "-dim 3 -timeout 5" "-dim 2 -timeout 5"
if [ $rf -ne 0 ] && [ $rs -ne 0 ] && grep -q "dimension differs" "$c/log.fluid" \
   && grep -q "dimension differs" "$c/log.solid" && no_segment "$c"; then
    pass "coupling handshake mismatch stops both: $(grep -m1 'differs' "$c/log.fluid" | cut -c1-100)"
else
    fail "coupling handshake mismatch" "exit $rf/$rs"
fi
newcase
pair "$c" "-digest A -timeout 5" "-digest B -timeout 5"
if [ $rf -ne 0 ] && [ $rs -ne 0 ] && grep -q "coupling settings" "$c/log.solid" \
   && no_segment "$c"; then
    pass "coupling handshake: different coupling settings refused"
else
    fail "coupling handshake settings digest" "exit $rf/$rs"
fi

# ---- stale segments ------------------------------------------------------------------
newcase
"$PEER" -side fluid -case "$c" -timeout 30 > "$c/log.dead" 2>&1 &
p=$!
for i in $(seq 100); do [ -e "$(segname "$c")" ] && break; sleep 0.02; done
kill -KILL $p; wait $p 2> /dev/null
left=$(ls "$(segname "$c")" 2> /dev/null)
pair "$c" "-frames 10" "-frames 10"
if [ -n "$left" ] && [ $rf -eq 0 ] && [ $rs -eq 0 ] && cat "$c/log.fluid" "$c/log.solid" \
   | grep -q "Removing stale" && no_segment "$c"; then
    pass "coupling stale segment of a killed creator replaced"
else
    fail "coupling stale segment (creator)" "left='$left' exit $rf/$rs"
fi

newcase
"$PEER" -side fluid -case "$c" -frames 1000000 -work 1000 > "$c/log.f0" 2>&1 &
pf=$!
"$PEER" -side solid -case "$c" -frames 1000000 -work 1000 > "$c/log.s0" 2>&1 &
ps=$!
sleep 0.5
kill -STOP $pf $ps; kill -KILL $pf $ps; wait $pf $ps 2> /dev/null
left=$(ls "$(segname "$c")" 2> /dev/null)
pair "$c" "-frames 10" "-frames 10"
if [ -n "$left" ] && [ $rf -eq 0 ] && [ $rs -eq 0 ] && no_segment "$c"; then
    pass "coupling stale segment of a killed pair replaced"
else
    fail "coupling stale segment (pair)" "left='$left' exit $rf/$rs"
fi

# ---- second pair ---------------------------------------------------------------------
newcase
"$PEER" -side fluid -case "$c" -frames 1500 -work 1000 > "$c/log.f1" 2>&1 &
pf=$!
"$PEER" -side solid -case "$c" -frames 1500 -work 1000 > "$c/log.s1" 2>&1 &
ps=$!
sleep 0.4
t0=$EPOCHREALTIME
"$PEER" -side fluid -case "$c" > "$c/log.f2" 2>&1; r3=$?
"$PEER" -side solid -case "$c" > "$c/log.s2" 2>&1; r4=$?
t1=$EPOCHREALTIME
wait $pf; rf=$?
wait $ps; rs=$?
if [ $r3 -ne 0 ] && [ $r4 -ne 0 ] && grep -q "second pair" "$c/log.f2" \
   && grep -q "second pair" "$c/log.s2" && [ $rf -eq 0 ] && [ $rs -eq 0 ] \
   && no_segment "$c"; then
    pass "coupling second pair refused in $(echo "$t1 - $t0" | bc) s, first pair unharmed"
else
    fail "coupling second pair" "exit $r3/$r4, first pair $rf/$rs"
fi

# ---- runTandem -------------------------------------------------------------------------
. "$ROOT/bin/tools/RunFunctions"

# two differently named programs, as mpsFluid and demSolid
mkdir -p "$TMP/bin"
printf '#!/bin/sh\nexec "%s" -side fluid "$@"\n' "$PEER" > "$TMP/bin/fakeFluid"
printf '#!/bin/sh\nexec "%s" -side solid "$@"\n' "$PEER" > "$TMP/bin/fakeSolid"
chmod +x "$TMP/bin/fakeFluid" "$TMP/bin/fakeSolid"
F="$TMP/bin/fakeFluid"; S="$TMP/bin/fakeSolid"

newcase
( cd "$c" && runTandem "$F -frames 200" "$S -frames 200" ) > "$c/out" 2>&1
r=$?
if [ $r -eq 0 ] && grep -q "End: 200" "$c/log.fakeFluid" && grep -q "End: 200" "$c/log.fakeSolid" \
   && no_segment "$c"; then
    pass "coupling runTandem: both succeed, logs log.fakeFluid log.fakeSolid"
else
    fail "coupling runTandem success" "exit $r; $(tail -n 3 "$c/out")"
fi

newcase
t0=$EPOCHREALTIME
( cd "$c" && runTandem "$F -frames 200 -timeout 60" "$S -badOption" ) > "$c/out" 2>&1
r=$?
t1=$EPOCHREALTIME
dt=$(echo "$t1 - $t0" | bc)
# (the fluid either reports SIGTERM or, stopped before it could catch
# signals, dies of it; either way it must not have run to its end)
if [ $r -ne 0 ] && ! grep -q "End:" "$c/log.fakeFluid" \
   && [ "$(echo "$dt < 5" | bc)" = 1 ] && no_segment "$c"; then
    pass "coupling runTandem: one program fails, the other is stopped (${dt} s)"
else
    fail "coupling runTandem failure" "exit $r in $dt s; $(tail -n 3 "$c/out")"
fi

newcase
set -m   # the tandem in its own process group, able to trap SIGINT
( cd "$c" && runTandem "$F -frames 100000000 -work 500" "$S -frames 100000000 -work 500" ) > "$c/out" 2>&1 &
pt=$!
set +m
sleep 0.8
t0=$EPOCHREALTIME
kill -INT $pt
wait $pt
r=$?
t1=$EPOCHREALTIME
dt=$(echo "$t1 - $t0" | bc)
if [ $r -ne 0 ] && grep -q "interrupted by signal INT" "$c/log.fakeFluid" \
   && grep -q "interrupted by signal INT" "$c/log.fakeSolid" \
   && ls "$c"/*/uniform/couplingPeer.fluid > /dev/null 2>&1 \
   && ls "$c"/*/uniform/couplingPeer.solid > /dev/null 2>&1 \
   && [ "$(echo "$dt < 2" | bc)" = 1 ] && no_segment "$c"; then
    pass "coupling SIGINT of the tandem: both stop in ${dt} s, last states written"
else
    fail "coupling SIGINT of the tandem" "exit $r in $dt s; $(tail -n 5 "$c/out")"
fi

[ $fails -eq 0 ]
