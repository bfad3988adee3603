#!/usr/bin/env bash
# frontEndBadInput.sh — bad input at the level of whole programs: each must
# stop with exit 1, a FATAL ERROR naming the file (and line, where there is
# one) and leave no partial output behind.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
BIN="${MPSDEM_BIN:-$ROOT/bin}"
work=$(mktemp -d /tmp/mpsdem_badinput_XXXXXX)
trap 'rm -rf "$work"' EXIT
status=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; status=1; }

# expect NAME LOG PATTERN RC : rc must be 1 and the log must match PATTERN
expect()
{
    if [ "$4" -ne 1 ]; then fail "$1" "exit status $4, expected 1"
    elif ! grep -q 'FATAL ERROR' "$2"; then fail "$1" "no FATAL ERROR"
    elif ! grep -qE "$3" "$2"; then fail "$1" "message does not match '$3': $(grep -A1 FATAL "$2" | tail -1)"
    else pass "$1"; fi
}

fresh()   # a small DEM case: one bead dropped in a box
{
    rm -rf "$work/case"; cp -r "$ROOT/tutorials/demSolid/bouncingSphere" "$work/case"
    (cd "$work/case" && "$BIN/genParticles" > /dev/null 2>&1)
}

# 1. A case directory that does not exist.
"$BIN/demSolid" -case "$work/nowhere" > "$work/log" 2>&1; rc=$?
expect missingCase "$work/log" "case directory .*nowhere.* does not exist" $rc

# 2. Unwritable output: 0 is a file, so genParticles cannot create 0/*.vtu.
fresh; rm -rf "$work/case/0" "$work/case/"*.pvd; touch "$work/case/0"
(cd "$work/case" && "$BIN/genParticles" > "$work/log" 2>&1); rc=$?
expect unwritableCase "$work/log" "0/fluid.vtu|0/dem.vtu" $rc
left=$(ls "$work/case" | grep -cE '\.tmp|\.pvd$')
[ "$left" -eq 0 ] && pass unwritableCaseNoPartialOutput || fail unwritableCaseNoPartialOutput "$left files left"

# 3. endTime before startTime, reported by the solver with file:line.
fresh
"$BIN/dictTool" -case "$work/case" system/controlDict -set startTime=1 > /dev/null
"$BIN/dictTool" -case "$work/case" system/controlDict -set endTime=0.5 > /dev/null
(cd "$work/case" && "$BIN/demSolid" > "$work/log" 2>&1); rc=$?
expect endBeforeStart "$work/log" "system/controlDict:[0-9]+:[0-9]+: endTime \(0.5\) is before startTime \(1\)" $rc

# 4. A truncated .vtu in the latest time directory at restart.
fresh
mkdir -p "$work/case/0.001"
head -c 300 "$work/case/0/dem.vtu" > "$work/case/0.001/dem.vtu"
"$BIN/dictTool" -case "$work/case" system/controlDict -set startFrom=latestTime > /dev/null
before=$(ls -R "$work/case" | md5sum)
(cd "$work/case" && "$BIN/demSolid" > "$work/log" 2>&1); rc=$?
expect truncatedVtu "$work/log" "0.001/dem.vtu" $rc
after=$(ls -R "$work/case" | grep -v '^log' | md5sum)
[ "$before" = "$after" ] && pass truncatedVtuNoOutput || fail truncatedVtuNoOutput "the case changed"

# 5. A corrupted (not truncated) .vtu: a byte of base64 replaced.
fresh
"$BIN/dictTool" -case "$work/case" system/particleDict -set writeFormat=binary > /dev/null
(cd "$work/case" && "$BIN/genParticles" > /dev/null 2>&1)
grep -q 'format="binary"' "$work/case/0/dem.vtu" || fail corruptedVtu "no binary array to corrupt"
mkdir -p "$work/case/0.001"
sed 's/format="binary">\(.\)/format="binary">!/' "$work/case/0/dem.vtu" > "$work/case/0.001/dem.vtu"
"$BIN/dictTool" -case "$work/case" system/controlDict -set startFrom=latestTime > /dev/null
(cd "$work/case" && "$BIN/demSolid" > "$work/log" 2>&1); rc=$?
expect corruptedVtu "$work/log" "0.001/dem.vtu" $rc

# 6. An unknown option.
"$BIN/genParticles" -caes x > "$work/log" 2>&1; rc=$?
expect unknownOption "$work/log" "unknown option '-caes'" $rc

# Out-of-range and non-finite input (issue 14 item 5): refused at read time
# naming the file and key (or field and point), and nothing written.
# snapshot: the case's files and their contents, logs and locks aside
snapshot() { (cd "$work/case" && find . -type f ! -name 'log*' ! -name '.*.lock' \
                  | sort | xargs md5sum | md5sum); }
# refused NAME PROGRAM PATTERN: PROGRAM fails with PATTERN, the case unchanged
refused()
{
    local before; before=$(snapshot)
    # a time limit: a coupled program whose bad key went unnoticed waits
    # for its peer, a tank whose bad input did not stop it runs for minutes
    (cd "$work/case" && timeout 60 "$BIN/$2" > "$work/log" 2>&1); rc=$?
    expect "$1" "$work/log" "$3" $rc
    [ "$before" = "$(snapshot)" ] && pass "$1NoOutput" || fail "$1NoOutput" "the case changed"
}
coupled()   # one grain settling in water: mpsFluid and demSolid coupled
{
    rm -rf "$work/case"; cp -r "$ROOT/tutorials/mpsDem/singleGrainSettling" "$work/case"
    (cd "$work/case" && "$BIN/genParticles" > /dev/null 2>&1)
}
tank()      # a 2-D hydrostatic tank, fixed deltaT, ascii clouds
{
    rm -rf "$work/case"; cp -r "$ROOT/tutorials/mpsFluid/hydrostaticTank2D" "$work/case"
    "$BIN/dictTool" -case "$work/case" system/particleDict -new -set writeFormat=ascii > /dev/null
    (cd "$work/case" && "$BIN/genParticles" > /dev/null 2>&1)
}

# 7. couplingDict times that overflowed the channel's nanosecond clocks.
coupled
"$BIN/dictTool" -case "$work/case" system/couplingDict -set timeout=1e11 > /dev/null
refused couplingTimeout demSolid "system/couplingDict:[0-9]+:[0-9]+: timeout must be in \(0, 1e\+08\] \[s\], not 1e\+11"
coupled
"$BIN/dictTool" -case "$work/case" system/couplingDict -new -set timeout=1e8 \
    -set heartbeatInterval=2e10 > /dev/null
refused couplingHeartbeat mpsFluid "system/couplingDict:[0-9]+:[0-9]+: heartbeatInterval must be in \(0, timeout = 1e\+08\] \[s\], not 2e\+10"

# 8. A step that does not advance time.
tank
"$BIN/dictTool" -case "$work/case" system/controlDict -set deltaT=1e-300 > /dev/null
refused tinyDeltaT mpsFluid "system/controlDict:[0-9]+:[0-9]+: deltaT = 1e-300 is too small for times up to 1 s: t \+ deltaT == t"

# 9. A start state holding inf.
tank
sed -i '/Name="pressure"/{n;s/^[^ ]*/inf/}' "$work/case/0/fluid.vtu"
refused infPressure mpsFluid "0/fluid.vtu: point field 'pressure' holds inf at point 0 \(id 0\), component 0"

# 10. A stray particle at x = 1e300: named with its id and file.
tank
sed -i '/<Points>/{n;n;s/^[^ ]*/1e300/}' "$work/case/0/fluid.vtu"
refused strayParticle mpsFluid "0/fluid.vtu: particle \(id 0, point 0\) at \(1e\+300 .*\) lies 1e\+300 m from the median"
exit $status
