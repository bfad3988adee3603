#!/usr/bin/env bash
# gravityDefault.sh — constant/g is treated the same way by every program
# (issue 15 item 5): when the file exists its value is echoed in the log
# and recorded in postProcessing/usedParameters/<program>; when it is
# missing the default ((0 0 -9.81) in 3-D, (0 -9.81 0) in 2-D) is used with
# a WARNING naming constant/g and the value, and recorded there as a
# default. The default gives the same numbers, to the bit, as a file
# holding that value; a bad file is still an error at its file:line.
#   demSolid      3-D, tutorials/demSolid/bouncingSphere (0.5 ms)
#   mpsFluid      2-D, tutorials/mpsFluid/hydrostaticTank2D (10 steps)
#   genParticles  3-D hydrostatic pressure, test/cases/genParticles
set -u
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
BIN=${MPSDEM_BIN:-$ROOT/bin}
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
export OMP_NUM_THREADS=1   # bit-for-bit comparisons
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
for b in demSolid mpsFluid genParticles vtuInfo dictTool; do
    [ -x "$BIN/$b" ] || { fail gravityDefault "bin/$b not built"; exit 1; }
done
T="$BIN/dictTool"

# the usedParameters block of constant/g, on one line
used_g() {  # case program
    awk '/^"[^"]*constant\/g"$/ { go = 1; next } go && /^}/ { exit }
         go && NF && !/^{$/ { sub(/^ +/, ""); printf "%s ", $0 }' \
        "$1/postProcessing/usedParameters/$2" | sed 's/  */ /g; s/ $//'
}
# the last written cloud, dumped (points and fields)
last_dump() {  # case file
    local t
    t=$(cd "$1" && ls -d [0-9]* | sort -g | tail -1)
    "$BIN/vtuInfo" -case "$1" -dump "$t/$2" | sed -n '/^# x/,$p'
}
# check_program NAME CASE-WITH-FILE CASE-WITHOUT PROGRAM VALUE DIM
check_program() {
    local name=$1 with=$2 without=$3 prog=$4 value=$5 dim=$6
    local echo_re="Gravity g = \\($value\\) m/s\\^2 from .*constant/g"
    local warn_re="WARNING: .*constant/g not found: gravity g = \\($value\\) m/s\\^2 assumed \\(the $dim-D default\\)"
    if grep -qE "$echo_re" "$with/log.$prog"; then
        pass "${name}_echo: $(grep -m1 -oE "$echo_re" "$with/log.$prog")"
    else fail "${name}_echo" "no '$echo_re' in log.$prog"; fi
    if grep -qE "$warn_re" "$without/log.$prog"; then
        pass "${name}_warning: $(grep -m1 -oE 'WARNING: .*' "$without/log.$prog" | sed 's|/tmp/[^ ]*/||')"
    else fail "${name}_warning" "no '$warn_re' in log.$prog"; fi
    if grep -q 'Gravity g = ' "$without/log.$prog" \
        || grep -q 'constant/g not found' "$with/log.$prog"; then
        fail "${name}_one_message" "echo and warning mixed up"
    fi
    local u
    u=$(used_g "$with" "$prog")
    if echo "$u" | grep -qE "value +\\($value\\);" && ! echo "$u" | grep -q default
    then pass "${name}_usedParameters_file: $u"
    else fail "${name}_usedParameters_file" "constant/g block '$u'"; fi
    u=$(used_g "$without" "$prog")
    if echo "$u" | grep -qE "^value +\\($value\\); // default$"
    then pass "${name}_usedParameters_default: $u"
    else fail "${name}_usedParameters_default" "constant/g block '$u'"; fi
}

# ---- demSolid, 3-D -----------------------------------------------------------
for v in file missing; do
    c="$TMP/dem_$v"
    cp -r "$ROOT/tutorials/demSolid/bouncingSphere" "$c"
    "$T" "$c/system/controlDict" -set "endTime=0.0005" > /dev/null
    "$T" "$c/system/controlDict" -set "deltaT=1e-5" > /dev/null
    "$T" "$c/system/controlDict" -set "writeInterval=0.0005" > /dev/null
    "$T" "$c/constant/g" -set "value=(0 0 -9.81)" > /dev/null
    [ $v = missing ] && rm "$c/constant/g"
    (cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1 \
        && "$BIN/demSolid" > log.demSolid 2>&1) \
        || fail "dem_run_$v" "$(grep -h -A1 FATAL "$c"/log.* | tail -1)"
done
check_program demSolid "$TMP/dem_file" "$TMP/dem_missing" demSolid "0 0 -9.81" 3
if [ -n "$(last_dump "$TMP/dem_file" dem.vtu)" ] &&
   cmp -s <(last_dump "$TMP/dem_file" dem.vtu) <(last_dump "$TMP/dem_missing" dem.vtu)
then pass "demSolid_default_same_result (grains at 0.5 ms identical to g = (0 0 -9.81) from the file)"
else fail demSolid_default_same_result "dem.vtu differs from the run with constant/g"; fi

# a file that exists but is wrong is an error, not the default
c="$TMP/dem_bad"; cp -r "$TMP/dem_file" "$c"
"$T" "$c/constant/g" -set "value=(0 -9.81)" > /dev/null
if ! (cd "$c" && "$BIN/demSolid" > log.bad 2>&1) &&
   grep -qE "constant/g:[0-9]+:[0-9]+: expected a vector of 3 numbers for 'value'" "$c/log.bad"
then pass "demSolid_bad_file: $(grep -m1 -oE 'constant/g:.*' "$c/log.bad")"
else fail demSolid_bad_file "$(grep -A1 FATAL "$c/log.bad" | tail -1)"; fi

# ---- mpsFluid, 2-D (a missing constant/g stopped it before) -----------------
for v in file missing; do
    c="$TMP/mps_$v"
    cp -r "$ROOT/tutorials/mpsFluid/hydrostaticTank2D" "$c"
    "$T" "$c/system/controlDict" -set "endTime=0.005" > /dev/null
    "$T" "$c/system/controlDict" -set "writeInterval=0.005" > /dev/null
    (cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1)
    [ $v = missing ] && rm "$c/constant/g"
    (cd "$c" && "$BIN/mpsFluid" > log.mpsFluid 2>&1) && grep -q '^End' "$c/log.mpsFluid" \
        || fail "mps_run_$v" "$(grep -A1 FATAL "$c/log.mpsFluid" | tail -1)"
done
check_program mpsFluid "$TMP/mps_file" "$TMP/mps_missing" mpsFluid "0 -9.81 0" 2
if [ -n "$(last_dump "$TMP/mps_file" fluid.vtu)" ] &&
   cmp -s <(last_dump "$TMP/mps_file" fluid.vtu) <(last_dump "$TMP/mps_missing" fluid.vtu)
then pass "mpsFluid_default_same_result (fluid at 5 ms identical to g = (0 -9.81 0) from the file)"
else fail mpsFluid_default_same_result "fluid.vtu differs from the run with constant/g"; fi

# ---- genParticles: hydrostatic pressure (a missing constant/g stopped it) ---
for v in file missing; do
    c="$TMP/gen_$v"
    cp -r "$ROOT/test/cases/genParticles" "$c"
    [ $v = missing ] && rm "$c/constant/g"
    (cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1) \
        || fail "gen_run_$v" "$(grep -A1 FATAL "$c/log.genParticles" | tail -1)"
done
check_program genParticles "$TMP/gen_file" "$TMP/gen_missing" genParticles "0 0 -9.81" 3
if cmp -s "$TMP/gen_file/0/fluid.vtu" "$TMP/gen_missing/0/fluid.vtu"
then pass "genParticles_default_same_result (hydrostatic pressure identical)"
else fail genParticles_default_same_result "0/fluid.vtu differs"; fi
# without hydrostaticPressure nothing reads gravity: nothing to warn about
c="$TMP/gen_nohydro"; cp -r "$TMP/gen_missing" "$c"
sed -i 's/hydrostaticPressure yes;//' "$c/system/particleDict"
(cd "$c" && "$BIN/genParticles" > log.genParticles 2>&1)
if ! grep -q 'constant/g' "$c/log.genParticles" && [ -z "$(used_g "$c" genParticles)" ]
then pass genParticles_gravity_unused_quiet
else fail genParticles_gravity_unused_quiet "constant/g mentioned though no region needs it"; fi

exit $((fails > 0))
