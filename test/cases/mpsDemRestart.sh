#!/usr/bin/env bash
# mpsDemRestart.sh — a coupled case survives what users do to it (issue 14
# items 2, 3 and 9), on the quick 2-D sedimentation set-up (15 beads, dp =
# 5 mm, Model B, 0.4 s written every 0.1 s, ~2 s a run):
#   second_start      starting mpsFluid and demSolid again on a case that is
#                     running fails at once, naming the running pid, and
#                     touches nothing: every postProcessing .dat and .pvd
#                     of the running pair still begins with what it held
#                     before, and the first pair runs to End
#   kill_<side>       after a SIGKILL of one program (fluid, then solid) at
#                     a random moment past 0.1 s (of 0.8 s), the survivor stops with a
#                     message; what it writes goes to failed.<t>/, no
#                     numeric time directory holds one cloud only, and a
#                     restart with startFrom latestTime runs to End from the
#                     newest time that holds both clouds
#   one_sided_time    a newer time directory with one cloud (as the former
#                     survivor dumps were) is skipped by latestTime, which
#                     says so in the log
#   debris            a "*.tmp.<pid>" of a dead writer and an empty time
#                     directory (what a kill during a write and a full disk
#                     left) are removed at the next start, each logged
#   full_disk         mpsFluid under a file-size limit (ulimit -f, SIGXFSZ
#                     ignored: writes fail with EFBIG as on a full disk)
#                     stops with an error naming the file, and leaves no
#                     empty time directory and no .tmp file
NAME=mpsDemRestart
. "$(dirname "$0")/lib/tandem.sh"

make_case()   # DIR CHANNEL
{
    local c="$1"
    case_beads_2d "$c"
    cat > "$c/system/controlDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
startFrom startTime; startTime 0; endTime 0.4; deltaT 4e-4; adjustTimeStep no;
writeControl runTime; writeInterval 0.1; writeFormat binary;
functions
{
    energy { type kineticEnergy; cloud dem; writeControl timeStep; writeInterval 5; }
    info   { type cloudInfo; cloud fluid; writeControl timeStep; writeInterval 5; }
}
EOD
    sed -i "s/^timeout .*/timeout 20;/" "$c/system/couplingDict"
    echo "channel $2;" >> "$c/system/couplingDict"
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
}

# one_cloud DIR: numeric time directories holding only one of the clouds
one_cloud()
{
    local d out=""
    for d in "$1"/[0-9]*/; do
        d=${d%/}
        [ -f "$d/fluid.vtu" ] && [ -f "$d/dem.vtu" ] && continue
        out="$out ${d##*/}"
    done
    echo "$out"
}

restart_to_end()   # DIR SUFFIX: startFrom latestTime, both to End
{
    sed -i 's/^startFrom startTime;/startFrom latestTime;/' "$1/system/controlDict"
    run_tandem "$1" 120 "$2"
}

# --- second start --------------------------------------------------------
c="$TMP/second"
make_case "$c" "mpsdem-rs2-$$" || { fail second_start "genParticles failed"; exit 1; }
(cd "$c" && timeout 120 "$MPSFLUID" > log.mpsFluid 2>&1) & p1=$!
(cd "$c" && timeout 120 "$DEMSOLID" > log.demSolid 2>&1) & p2=$!
for _ in $(seq 200); do
    [ -s "$c/postProcessing/energy/0/kineticEnergy.dat" ] \
        && [ "$(grep -vc '^#' "$c/postProcessing/energy/0/kineticEnergy.dat")" -ge 20 ] && break
    sleep 0.05
done
mkdir -p "$TMP/before"
for f in "$c"/postProcessing/*/0/*.dat "$c"/*.pvd; do cp "$f" "$TMP/before/${f//\//_}"; done
s=$EPOCHREALTIME
(cd "$c" && timeout 30 "$MPSFLUID" > log.mpsFluid.second 2>&1); r1=$?
(cd "$c" && timeout 30 "$DEMSOLID" > log.demSolid.second 2>&1); r2=$?
took=$(echo "$EPOCHREALTIME - $s" | bc)
wait $p1; q1=$?; wait $p2; q2=$?
bad=""
for f in "$c"/postProcessing/*/0/*.dat "$c"/*.pvd; do
    b="$TMP/before/${f//\//_}"
    if [[ "$f" == *.pvd ]]; then
        # every data set listed before is still listed
        while read -r l; do grep -qF "$l" "$f" || bad="$bad ${f##*/}"; done < <(grep 'DataSet' "$b")
    else
        n=$(stat -c %s "$b")
        cmp -s -n "$n" "$b" "$f" || bad="$bad ${f#$c/}"
    fi
done
if [ $r1 -ne 0 ] && [ $r2 -ne 0 ] && grep -q 'already running' "$c/log.mpsFluid.second" \
   && grep -q 'already running' "$c/log.demSolid.second" && [ -z "$bad" ] \
   && [ $q1 -eq 0 ] && [ $q2 -eq 0 ] && grep -q '^End' "$c/log.mpsFluid" && grep -q '^End' "$c/log.demSolid"; then
    pass "second_start refused in $took s: $(grep -m1 -o 'mpsFluid is already running.*pid [0-9]*' "$c/log.mpsFluid.second")"
else
    fail second_start "second exits $r1/$r2, first $q1/$q2, changed:${bad:- none}; $(grep -h -A1 FATAL "$c"/log.*.second | tr '\n' ' ' | cut -c1-200)"
fi

# --- a kill of either side, then latestTime to the end ---------------------
for side in fluid solid; do
    c="$TMP/kill_$side"
    make_case "$c" "mpsdem-rsk$side-$$" || { fail "kill_$side" "genParticles failed"; continue; }
    sed -i 's/endTime 0.4;/endTime 0.8;/' "$c/system/controlDict"
    # exec: the pids are the programs' own (the channel's time-out of 20 s
    # bounds a survivor that would not notice)
    (cd "$c" && exec "$MPSFLUID" > log.mpsFluid 2>&1) & pf=$!
    (cd "$c" && exec "$DEMSOLID" > log.demSolid 2>&1) & pd=$!
    for _ in $(seq 1000); do [ -f "$c/0.1/fluid.vtu" ] && [ -f "$c/0.1/dem.vtu" ] && break; sleep 0.01; done
    sleep "0.0$((RANDOM % 10))"
    if [ $side = fluid ]; then victim=$pf; survivor=$pd; else victim=$pd; survivor=$pf; fi
    kill -KILL $victim 2>/dev/null
    { wait $victim; } 2>/dev/null
    wait $survivor; rs=$?
    lone=$(one_cloud "$c")
    s_log="$c/log.$([ $side = fluid ] && echo demSolid || echo mpsFluid)"
    if [ $rs -ne 0 ] && [ -z "$lone" ] && grep -q 'FATAL' "$s_log"; then
        if restart_to_end "$c" restart; then
            from=$(grep -o 'Starting from the latest time, [0-9.e-]*' "$c/log.mpsFluid.restart" | awk '{print $NF}')
            pass "kill_$side restart from $from to End ($(ls -d "$c"/failed.* 2>/dev/null | sed 's|.*/||' | tr '\n' ' ')left by the survivor)"
        else
            fail "kill_$side" "restart failed: $rf/$rd $(fatal_of "$c")"
        fi
    else
        fail "kill_$side" "survivor exit $rs, one-cloud time directories:${lone:- none}"
    fi
done

# --- a newer one-sided time and debris, then latestTime --------------------
c="$TMP/kill_fluid"
if [ -d "$c/0.8" ]; then
    mkdir -p "$c/0.9" "$c/1" && cp "$c/0.8/dem.vtu" "$c/0.9/dem.vtu"
    touch "$c/0.8/fluid.vtu.tmp.999999999"
    sed -i 's/endTime 0.8;/endTime 0.9;/' "$c/system/controlDict"
    if run_tandem "$c" 120 again; then
        grep -q 'newer time directories that do not hold every cloud of the run are skipped: 0.9 (no fluid.vtu)' \
            "$c/log.mpsFluid.again" \
            && grep -q 'Starting from the latest time, 0.8' "$c/log.mpsFluid.again" \
            && pass one_sided_time || fail one_sided_time "$(grep -m1 -A1 'latestTime' "$c/log.mpsFluid.again" | tr '\n' ' ')"
        [ ! -e "$c/0.8/fluid.vtu.tmp.999999999" ] && [ ! -e "$c/1" ] \
            && grep -q "Removed the empty time directory" "$c"/log.*.again \
            && grep -q "left by a run killed while writing" "$c"/log.*.again \
            && pass debris || fail debris "tmp file or empty 1/ still there, or not logged"
    else
        fail one_sided_time "run failed: $rf/$rd $(fatal_of "$c")"
    fi
else
    fail one_sided_time "the restarted kill_fluid case has no 0.8"
fi

# --- full disk ------------------------------------------------------------
c="$TMP/full"
mkdir -p "$c"
cp -r "$ROOT/tutorials/mpsFluid/hydrostaticTank2D/." "$c/"
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
"$ROOT/bin/dictTool" "$c/system/controlDict" -set "endTime=0.05" > /dev/null
"$ROOT/bin/dictTool" "$c/system/controlDict" -set "writeInterval=0.01" > /dev/null
"$ROOT/bin/dictTool" "$c/system/controlDict" -set "writeFormat=ascii" > /dev/null
# the first write of fluid.vtu (~100 KB in ascii) exceeds 40 KB; the log
# goes to a pipe, which the limit does not cover
(cd "$c" && trap '' XFSZ && ulimit -f 40 && timeout 60 "$MPSFLUID" 2>&1 | cat > log.mpsFluid); rfull=${PIPESTATUS[0]}
empty=$(find "$c" -mindepth 1 -maxdepth 1 -type d -empty -name '[0-9]*' | sed 's|.*/||' | tr '\n' ' ')
tmps=$(find "$c" -name '*.tmp.*' | wc -l)
if grep -q 'FATAL' "$c/log.mpsFluid" && grep -q 'fluid.vtu' "$c/log.mpsFluid" && [ -z "$empty" ] && [ "$tmps" -eq 0 ]; then
    pass "full_disk: $(grep -m1 -A1 'FATAL' "$c/log.mpsFluid" | tail -1 | sed 's/^ *//' | cut -c1-120)"
else
    fail full_disk "empty time directories: ${empty:-none}; tmp files $tmps; $(grep -m1 -A1 FATAL "$c/log.mpsFluid" | tr '\n' ' ')"
fi
exit $((fails > 0))
