#!/usr/bin/env bash
# couplingKill.sh — one of two coupled programs (bin/couplingPeer, a test
# tool) is killed with SIGKILL at random moments: before the other starts,
# during the handshake, in the middle of a frame (frames of up to 3x10^4
# grains), or while the other waits (random 'computation' per step on each
# side; one run in three streams frames one way, so that the sender waits
# for free slots in a full ring). The survivor must always exit != 0 within 2 s of the kill with a
# message, write its last complete state, and leave nothing in /dev/shm.
#
#   COUPLING_KILLS=N   number of kills (default 100; test/bench runs more)
#   COUPLING_SEED=S    random seed (default 1)
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
PEER="$ROOT/bin/couplingPeer"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
N="${COUPLING_KILLS:-100}"
RANDOM="${COUPLING_SEED:-1}"
TIMEOUT=1.0    # handshake time-out of the peers [s]

[ -x "$PEER" ] || { echo "FAIL couplingKill: bin/couplingPeer not built"; exit 1; }

ms() { printf '0.%03d' "$1"; }   # milliseconds (< 1000) as seconds

ok=0; slow=0; silent=0; nostate=0; left=0; badvictim=0
worst=0; worst_at=""; worst_seen=0   # worst_seen: victim had attached
declare -A how
for i in $(seq "$N"); do
    c="$TMP/k$i"
    mkdir -p "$c"
    name=$(cd "$c" && "$PEER" -side fluid -printName)
    if [ $((RANDOM % 2)) -eq 0 ]; then vs=fluid; ss=solid; else vs=solid; ss=fluid; fi
    grains=(1 1000 30000); g=${grains[RANDOM % 3]}
    works=(0 300 2000); wv=${works[RANDOM % 3]}; ws=${works[RANDOM % 3]}
    if [ $((RANDOM % 4)) -eq 0 ]; then dv=$((RANDOM % 20)); else dv=$((20 + RANDOM % 230)); fi
    gap=$((RANDOM % 60))
    args="-case $c -frames 1000000000 -grains $g -timeout $TIMEOUT -quiet"
    # one in three: DEM states streamed without answers, so that a sender
    # also waits for a free slot in a full ring
    [ $((RANDOM % 3)) -eq 0 ] && args="$args -oneway"
    if [ $((RANDOM % 2)) -eq 0 ]; then          # survivor first
        "$PEER" -side $ss $args -work $ws > "$c/log.$ss" 2>&1 & ps=$!
        sleep "$(ms $gap)"
        "$PEER" -side $vs $args -work $wv > "$c/log.$vs" 2>&1 & pv=$!
        sleep "$(ms $dv)"
        tk=$EPOCHREALTIME; kill -KILL $pv
    else                                        # victim first
        "$PEER" -side $vs $args -work $wv > "$c/log.$vs" 2>&1 & pv=$!
        if [ $gap -lt $dv ]; then
            sleep "$(ms $gap)"
            "$PEER" -side $ss $args -work $ws > "$c/log.$ss" 2>&1 & ps=$!
            sleep "$(ms $((dv - gap)))"
            tk=$EPOCHREALTIME; kill -KILL $pv
        else
            sleep "$(ms $dv)"
            tk=$EPOCHREALTIME; kill -KILL $pv
            sleep "$(ms $((gap - dv)))"
            "$PEER" -side $ss $args -work $ws > "$c/log.$ss" 2>&1 & ps=$!
        fi
    fi
    { wait $ps; rs=$?; } 2> /dev/null    # no "Killed" job notices
    te=$EPOCHREALTIME
    { wait $pv; rv=$?; } 2> /dev/null
    delay=$(echo "$te - $tk" | bc)
    what="case $i (victim $vs at ${dv} ms, gap ${gap} ms, $g grains)"
    msg=$(grep -m1 -E 'died without|exited before|no peer program|closed the channel|no heartbeat|stopped with' "$c/log.$ss")
    if [ "$rs" -eq 0 ] || ! grep -q 'FATAL ERROR' "$c/log.$ss" || [ -z "$msg" ]; then
        silent=$((silent + 1))
        [ $silent -le 3 ] && echo "FAIL couplingKill: $what: survivor exit $rs, log: $(tail -n 3 "$c/log.$ss" | tr '\n' ' ')"
    fi
    if [ "$(echo "$delay > 2.0" | bc)" = 1 ]; then
        slow=$((slow + 1))
        [ $slow -le 3 ] && echo "FAIL couplingKill: $what: survivor took $delay s"
    fi
    if [ "$(echo "$delay > $worst" | bc)" = 1 ]; then worst=$delay; worst_at="$what"; fi
    if ! ls "$c"/*/uniform/couplingPeer.$ss > /dev/null 2>&1; then
        nostate=$((nostate + 1))
        [ $nostate -le 3 ] && echo "FAIL couplingKill: $what: no last state written"
    fi
    if ls /dev/shm"$name" /dev/shm"$name".init.* > /dev/null 2>&1; then
        left=$((left + 1))
        [ $left -le 3 ] && echo "FAIL couplingKill: $what: segment left: $(ls /dev/shm | grep "${name#/}")"
        rm -f /dev/shm"$name" /dev/shm"$name".init.*
    fi
    [ "$rv" -ne 137 ] && badvictim=$((badvictim + 1))
    key=$(echo "$msg" | grep -o -E 'died without closing|exited before the handshake|no peer program attached|closed the channel|no heartbeat|stopped with an error')
    # where the survivor was: handshake, waiting for a frame, for a slot
    at=$(grep -m1 -o -E 'in (handshake|channel_recv|channel_send_begin|connect_segment) ' "$c/log.$ss")
    key="$key, ${at:-elsewhere}"
    how[$key]=$(( ${how[$key]:-0} + 1 ))
    case "$key" in
        "died without"*|"exited before"*)
            [ "$(echo "$delay > $worst_seen" | bc)" = 1 ] && worst_seen=$delay ;;
    esac
    rm -rf "$c"
done 2> "$TMP/stderr"   # bash reports each killed job there
grep -v ' Killed ' "$TMP/stderr" >&2

echo "survivor messages, and where the survivor was waiting:"
for k in "${!how[@]}"; do printf '  %4d  %s\n' "${how[$k]}" "$k"; done
echo "worst exit delay after the kill: $worst s ($worst_at)"
echo "worst exit delay when the victim had attached (seen through its pidfd): $worst_seen s"
echo "(otherwise the survivor never saw a peer and stops at its $TIMEOUT s time-out)"
[ $badvictim -gt 0 ] && echo "note: $badvictim victims were not killed by SIGKILL (they had already stopped)"

[ $silent -eq 0 ] && echo "PASS couplingKill: $N kills, every survivor stopped with exit != 0 and a message" \
    || echo "FAIL couplingKill: $silent of $N survivors ended without error and message"
[ $slow -eq 0 ] && echo "PASS couplingKill: worst survivor exit $worst s after the kill (limit 2 s)" \
    || echo "FAIL couplingKill: $slow of $N survivors took more than 2 s (worst $worst s)"
[ $nostate -eq 0 ] && echo "PASS couplingKill: last complete state written by all $N survivors" \
    || echo "FAIL couplingKill: $nostate of $N survivors wrote no last state"
[ $left -eq 0 ] && echo "PASS couplingKill: segments left in /dev/shm: 0" \
    || echo "FAIL couplingKill: segments left in /dev/shm after $left of $N kills"
[ $silent -eq 0 ] && [ $slow -eq 0 ] && [ $nostate -eq 0 ] && [ $left -eq 0 ]
