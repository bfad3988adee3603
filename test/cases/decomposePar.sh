#!/usr/bin/env bash
# decomposePar.sh — the decomposition report of an mpsFluid case
# (applications/utilities/decomposePar, particles/decompose.h):
#   decompose_report   damBreak2D cut in 3: three subdomains whose
#                      particles add up to the cloud's, the fluid weight
#                      balanced (imbalance <= 1.01), a halo, messages in
#                      pairs (each neighbour relation counted from both
#                      sides)
#   decompose_one      one subdomain: no halo, no message
#   decompose_bad      no -dry-run, numberOfSubdomains 0, an unknown
#                      method, a missing dictionary: exit 1, a message
#                      naming the file (and line, key) and nothing written
set -u
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
BIN=${MPSDEM_BIN:-$ROOT/bin}
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
C="$TMP/case"
cp -r "$ROOT/tutorials/mpsFluid/damBreak2D" "$C"
(cd "$C" && "$BIN/genParticles" > log.genParticles 2>&1) || { fail decompose_report "genParticles failed"; exit 1; }
dict() {
    printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n%s\n' "$1" \
        > "$C/system/decomposeParDict"
}
dict "numberOfSubdomains 3;
method rcb;"
out=$("$BIN/decomposePar" -case "$C" -dry-run 2>&1)
total=$(echo "$out" | sed -n 's/^Decomposing .*: \([0-9]*\) particles.*/\1/p')
bad=$(echo "$out" | awk -v total="$total" '
    /^ +subdomain/ { t = 1; next } t && NF == 5 && $1 ~ /^[0-9]+$/ { rows++; sum += $2; halo += $4; msg += $5; next }
    t && NF != 5 { t = 0 }
    /imbalance/ { im = $NF; gsub(/\)/, "", im) }
    END { if (rows != 3) print rows " rows (3 expected)"
          if (sum != total) print "particles add up to " sum ", not " total
          if (!(im + 0 <= 1.01)) print "imbalance " im
          if (!(halo > 0)) print "no halo"
          if (msg % 2 || msg < 4) print msg " messages" }')
[ -n "$total" ] && [ -z "$bad" ] && pass decompose_report || fail decompose_report "${bad:-no report: $(echo "$out" | tail -n 3 | tr '\n' ' ')}"
out=$("$BIN/decomposePar" -case "$C" -dry-run -subdomains 1 2>&1)
echo "$out" | grep -q "halo particles *0 in total" && echo "$out" | grep -q ": 0 messages per exchange" \
    && pass decompose_one || fail decompose_one "$(echo "$out" | grep -E 'halo|messages' | tr '\n' ' ')"
# bad input: exit 1, the file named, nothing written
check_bad() {  # label expected-message-part args...
    local label=$1 want=$2; shift 2
    local before after o
    touch "$TMP/stamp"
    before=$(cd "$C" && find . -newer "$TMP/stamp" | sort)
    o=$("$BIN/decomposePar" -case "$C" "$@" 2>&1); local rc=$?
    after=$(cd "$C" && find . -newer "$TMP/stamp" | sort)
    if [ $rc -eq 1 ] && echo "$o" | grep -q "$want" && [ "$before" = "$after" ]; then
        return 0
    fi
    echo "$label: exit $rc, $(echo "$o" | grep -A1 FATAL | tail -n 1)"
    return 1
}
msg=""
check_bad no-dry-run "run \`decomposePar -dry-run\`" || msg+=" no-dry-run"
dict "numberOfSubdomains 0;"
check_bad zero "system/decomposeParDict:2:1: numberOfSubdomains 0" -dry-run || msg+=" zero"
dict "numberOfSubdomains 2;
method scotch;"
check_bad method "system/decomposeParDict:3:1: unknown decomposition method 'scotch'; valid: rcb" -dry-run || msg+=" method"
dict "numberOfSubdomains 2;
balance water;"
check_bad balance "system/decomposeParDict:3:9: unknown value 'water' for 'balance'; valid: fluid all" -dry-run || msg+=" balance"
rm "$C/system/decomposeParDict"
check_bad missing "cannot open '.*system/decomposeParDict'" -dry-run || msg+=" missing"
[ -z "$msg" ] && pass decompose_bad || fail decompose_bad "$msg"
exit $((fails > 0))
