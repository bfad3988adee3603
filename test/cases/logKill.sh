#!/bin/bash
# logKill.sh — a solver killed mid-run (SIGKILL, as the OOM killer or a
# crash would stop it) leaves a log that reaches its last completed step
# (issue 14 item 4: redirected logs were block-buffered and stopped 4 KB,
# seconds, before the end; a crashed run's log was cut inside its parameter
# dump).
#
# Each solver runs a tutorial with a function object that writes and
# flushes a line every step, before the step's "Time = " line goes to the
# log. Once that file has LINES lines the solver is killed; the log must
# then end with a whole line, hold the complete parameter dump ("Starting
# time loop") and a "Time = t" line for the step before the last one the
# function object recorded. A block-buffered log misses that line unless
# the kill falls within ~1 line of a 4 KB flush (about 1 in 40 per program).
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
BIN="${MPSDEM_BIN:-$ROOT/bin}"
WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
export OMP_NUM_THREADS=1
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
for b in genParticles demSolid mpsFluid dictTool; do
    [ -x "$BIN/$b" ] || { fail logKill "$BIN/$b not built"; exit 1; }
done

# kill_mid_run NAME PROGRAM CASE FOFILE LINES
kill_mid_run() {
    local name="$1" prog="$2" c="$3" fo="$3/$4" lines="$5" log="$3/log.$2"
    (cd "$c" && exec "$BIN/$prog" > "log.$prog" 2>&1) &
    local pid=$! k
    for k in $(seq 600); do   # 60 s at most
        [ -f "$fo" ] && [ "$(wc -l < "$fo")" -ge "$lines" ] && break
        kill -0 $pid 2>/dev/null || break
        sleep 0.1
    done
    kill -KILL $pid 2>/dev/null
    wait $pid 2>/dev/null
    if [ ! -f "$fo" ] || [ "$(wc -l < "$fo")" -lt "$lines" ]; then
        fail "$name" "$prog did not reach $lines lines of $4: $(grep -A2 FATAL "$log" | head -3 | tr '\n' ' ')"
        return
    fi
    # the time of the step before the last one the function object flushed
    local want last
    want=$(grep -v '^#' "$fo" | awk 'NF { p = q; q = $1 } END { print p }')
    last=$(awk '/^Time = / { t = $3 } END { print t }' "$log")
    if [ "$(tail -c 1 "$log" | od -An -c | tr -d ' ')" != '\n' ]; then
        fail "$name" "log.$prog ends inside a line: '$(tail -c 80 "$log" | tr '\n' '|')'"
    elif ! grep -q '^Starting time loop' "$log"; then
        fail "$name" "log.$prog lacks the end of the parameter dump ($(wc -c < "$log") bytes)"
    elif [ -z "$last" ] || ! awk -v l="$last" -v w="$want" 'BEGIN { exit !(l >= w * (1 - 1e-9)) }'; then
        fail "$name" "log.$prog stops at Time = ${last:-none}; the run had completed t = $want ($4)"
    else
        pass "$name: killed past t = $want, log.$prog reaches Time = $last"
    fi
}

c="$WORK/dem"
cp -r "$ROOT/tutorials/demSolid/bouncingSphere" "$c"
"$BIN/dictTool" "$c/system/controlDict" -set "endTime=100" > /dev/null
(cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1)
kill_mid_run demSolid_killed demSolid "$c" postProcessing/contacts/0/contacts.dat 2000

c="$WORK/mps"
cp -r "$ROOT/tutorials/mpsFluid/damBreak2D" "$c"
"$BIN/dictTool" "$c/system/controlDict" -set "endTime=100" > /dev/null
(cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1)
kill_mid_run mpsFluid_killed mpsFluid "$c" postProcessing/surge/0/front.dat 200
exit $((fails > 0))
