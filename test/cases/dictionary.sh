#!/usr/bin/env bash
# test/cases/dictionary.sh — dictTool over the dictionary corpus test/dictionary/.
#
#   <feature>.dict   expands to <feature>.expanded, which parses back to itself
#   bad_<case>.dict  fails (or warns) with the file:line:col and the phrase
#                    held in bad_<case>.err (line 1: location, line 2: phrase,
#                    optional line 3: "exit N", default 1); dictTool's
#                    arguments come from bad_<case>.args (default -expand)
# plus -entry, -keys and -set checks. One line PASS/FAIL per check.
set -u
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
TOOL=${DICTTOOL:-$ROOT/bin/dictTool}   # DICTTOOL=bin-san/dictTool for the sanitizer build
CORPUS=$ROOT/test/dictionary
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
nfail=0

pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; nfail=$((nfail + 1)); }

if [ ! -x "$TOOL" ]; then
    fail dictTool "bin/dictTool not built (make bin/dictTool)"
    exit 1
fi

# ---- features: expand, and the expansion is a fixed point -------------------
for f in "$CORPUS"/*.dict; do
    name=$(basename "$f" .dict)
    case $name in bad_*) continue ;; esac
    exp=$CORPUS/$name.expanded
    if [ ! -f "$exp" ]; then
        fail "expand_$name" "no $name.expanded"
        continue
    fi
    if ! "$TOOL" -case "$CORPUS" "$name.dict" -expand > "$TMP/out" 2> "$TMP/err"; then
        fail "expand_$name" "$(grep -m1 FATAL "$TMP/err")"
        continue
    fi
    if cmp -s "$TMP/out" "$exp"; then
        pass "expand_$name"
    else
        fail "expand_$name" "output differs from $name.expanded: $(diff "$exp" "$TMP/out" | head -3 | tr '\n' ' ')"
    fi
    cp "$TMP/out" "$TMP/again.dict"
    if "$TOOL" -case "$TMP" again.dict > "$TMP/out2" 2>&1 && cmp -s "$TMP/out" "$TMP/out2"; then
        pass "reparse_$name"
    else
        fail "reparse_$name" "the expansion does not parse back to itself"
    fi
done

# ---- bad input: location, message, exit status ------------------------------
for f in "$CORPUS"/bad_*.dict; do
    name=$(basename "$f" .dict)
    err=$CORPUS/$name.err
    [ -f "$err" ] || { fail "$name" "no $name.err"; continue; }
    where=$(sed -n 1p "$err")
    phrase=$(sed -n 2p "$err")
    want=$(sed -n 's/^exit //p' "$err"); want=${want:-1}
    args=-expand
    [ -f "$CORPUS/$name.args" ] && args=$(cat "$CORPUS/$name.args")
    # shellcheck disable=SC2086
    "$TOOL" -case "$CORPUS" "$name.dict" $args > "$TMP/out" 2> "$TMP/err"
    rc=$?
    line=$(cat "$TMP/out" "$TMP/err" | grep -F -- "$where" | grep -F -- "$phrase")
    if [ "$rc" -ne "$want" ]; then
        fail "$name" "exit status $rc, expected $want"
    elif [ -z "$line" ]; then
        fail "$name" "no '$where ... $phrase' in: $(cat "$TMP/err" "$TMP/out" | grep -v '^$' | head -2 | tr '\n' ' ')"
    elif [ "$want" -ne 0 ] && ! grep -q "FATAL ERROR" "$TMP/err"; then
        fail "$name" "no FATAL ERROR on stderr"
    else
        pass "$name"
    fi
done

# ---- -entry and -keys -------------------------------------------------------
check_out() { # name expected command...
    local name=$1 want=$2
    shift 2
    local got
    got=$("$@" 2>&1)
    if [ "$got" = "$want" ]; then pass "$name"; else fail "$name" "got '$got', expected '$want'"; fi
}
check_out entry_scalar "1" "$TOOL" -case "$CORPUS" comments.dict -entry endTime
check_out entry_scoped "1e-6" "$TOOL" -case "$CORPUS" scoped_substitution.dict -entry solvers/pFinal/tolerance
check_out entry_dict "$(printf '{\n    solver          PCG;\n    tolerance       1e-6;\n    relTol          0;\n}')" \
    "$TOOL" -case "$CORPUS" merge.dict -entry pFinal
check_out keys_top "$(printf 'p\npFinal\nU')" "$TOOL" -case "$CORPUS" merge.dict -keys
check_out keys_sub "$(printf 'tol\np\npFinal')" "$TOOL" -case "$CORPUS" scoped_substitution.dict -keys -entry solvers

# ---- -set: only the value changes, comments stay, bad values change nothing --
mkdir -p "$TMP/case/system"
cp "$CORPUS/comments.dict" "$TMP/case/system/controlDict"
"$TOOL" -case "$TMP/case" system/controlDict -set endTime=2.5 > /dev/null 2>&1
changed=$(diff "$CORPUS/comments.dict" "$TMP/case/system/controlDict" | grep -c '^[<>]')
new=$("$TOOL" -case "$TMP/case" system/controlDict -entry endTime 2>&1)
if [ "$changed" = 2 ] && [ "$new" = 2.5 ] \
   && grep -q 'endTime /\* inside an entry \*/ 2.5;' "$TMP/case/system/controlDict"; then
    pass set_in_place
else
    fail set_in_place "changed lines: $changed, new value '$new'"
fi
"$TOOL" -case "$TMP/case" system/controlDict -new -set functions/probes/type=probes > /dev/null 2>&1
check_out set_new_subdict "probes" "$TOOL" -case "$TMP/case" system/controlDict -entry functions/probes/type
cp "$TMP/case/system/controlDict" "$TMP/before"
if "$TOOL" -case "$TMP/case" system/controlDict -set 'endTime=1; x 2' > /dev/null 2> "$TMP/err"; then
    fail set_bad_value "accepted a value with a ';' in it"
elif cmp -s "$TMP/before" "$TMP/case/system/controlDict" && grep -q "FATAL ERROR" "$TMP/err"; then
    pass set_bad_value
else
    fail set_bad_value "file modified or no FATAL ERROR"
fi
# ---- several -set, and keys that are not in the file (issue 14 item 7) ------
"$TOOL" -case "$TMP/case" system/controlDict -set endTime=3 -set deltaT=2e-4 > /dev/null 2> "$TMP/err"
got="$("$TOOL" -case "$TMP/case" system/controlDict -entry endTime) $("$TOOL" -case "$TMP/case" system/controlDict -entry deltaT)"
[ "$got" = "3 2e-4" ] && pass set_several || fail set_several "endTime deltaT = '$got', want '3 2e-4' $(grep -m1 FATAL "$TMP/err")"
cp "$TMP/case/system/controlDict" "$TMP/before"
# a misspelt key is refused, with a suggestion, and nothing is written even
# for the good -set before it
if "$TOOL" -case "$TMP/case" system/controlDict -set endTime=4 -set deltaTT=1 > /dev/null 2> "$TMP/err"; then
    fail set_unknown_key "added a key that is not in the file"
elif ! cmp -s "$TMP/before" "$TMP/case/system/controlDict"; then
    fail set_unknown_key "the file changed"
elif grep -q "system/controlDict:[0-9]*:[0-9]*: no key 'deltaTT' to set (did you mean 'deltaT'?); a new key needs -new" "$TMP/err"; then
    pass set_unknown_key
else
    fail set_unknown_key "$(grep -m1 . "$TMP/err")"
fi
if "$TOOL" -case "$TMP/case" system/controlDict -set functions/probes/typ=x > /dev/null 2> "$TMP/err"; then
    fail set_unknown_subkey "added a key that is not in the file"
elif grep -q "system/controlDict:[0-9]*:[0-9]*: no key 'functions/probes/typ' to set (did you mean 'functions/probes/type'?)" "$TMP/err"; then
    pass set_unknown_subkey
else
    fail set_unknown_subkey "$(grep -m1 . "$TMP/err")"
fi
"$TOOL" -case "$TMP/case" system/controlDict -new -set writeInterval=0.1 -set endTime=5 > /dev/null 2> "$TMP/err"
got="$("$TOOL" -case "$TMP/case" system/controlDict -entry writeInterval 2>&1) $("$TOOL" -case "$TMP/case" system/controlDict -entry endTime 2>&1)"
[ "$got" = "0.1 5" ] && pass set_new_key || fail set_new_key "writeInterval endTime = '$got', want '0.1 5'"
if "$TOOL" -case "$TMP/case" system/controlDict -new -set endTime=6 -set endTime=7 > /dev/null 2> "$TMP/err"; then
    fail set_twice "accepted two values for one key"
elif grep -q "the edit of 'endTime' would be undone by the later one of 'endTime'" "$TMP/err"; then
    pass set_twice
else
    fail set_twice "$(grep -m1 . "$TMP/err")"
fi

if "$TOOL" -case "$TMP/case" system/missingDict > /dev/null 2> "$TMP/err"; then
    fail missing_file "exit status 0"
elif grep -q "cannot open 'system/missingDict': No such file or directory" "$TMP/err"; then
    pass missing_file
else
    fail missing_file "$(grep -m1 . "$TMP/err")"
fi

[ "$nfail" -eq 0 ]
