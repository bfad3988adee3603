#!/bin/bash
# statusTable.sh — the root README tells what the tutorials measured.
#   status_table     README.md's status table is exactly what
#                    bin/tools/statusTable gathers from the "Validation
#                    status" tables of the tutorial READMEs (a number changed
#                    in one place and not the other fails, naming the row)
#   status_rows      every row has 6 cells, "met" is yes, no or —, and the
#                    date is YYYY-MM-DD
#   status_pictures  every tutorial of tutorials/README.md has a committed
#                    picture in its validation/ (a PNG tracked by git)
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$ROOT" || exit 1
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT

if ! bin/tools/statusTable > "$TMP/want" 2> "$TMP/err"; then
    fail status_table "bin/tools/statusTable failed: $(cat "$TMP/err")"
else
    sed -n '/^<!-- status table begin/,/^<!-- status table end/p' README.md \
        | sed '1d;$d' > "$TMP/have"
    if cmp -s "$TMP/want" "$TMP/have"; then
        pass status_table
    else
        d=$(diff "$TMP/have" "$TMP/want" | grep '^[<>]' | head -n 4 | cut -c1-160 | tr '\n' ' ')
        fail status_table "README.md differs from the tutorials (run bin/tools/statusTable -update): $d"
    fi
fi

bad=$(awk -F'|' 'NR > 2 { n++
        met = $6; gsub(/ /, "", met); date = $8; gsub(/ /, "", date)
        if (NF != 9 || (met != "yes" && met != "no" && met != "—") || date !~ /^20[0-9][0-9]-[01][0-9]-[0-3][0-9]$/)
            print "row " NR ": " substr($0, 1, 80) }
        END { if (n < 10) print "only " n " rows" }' "$TMP/want")
[ -z "$bad" ] && pass status_rows || fail status_rows "$(echo "$bad" | head -n 3 | tr '\n' ' ')"

missing=""
for c in $(sed -n 's/^| `\([A-Za-z0-9]*\/[A-Za-z0-9]*\)` |.*/\1/p' tutorials/README.md); do
    [ -n "$(git ls-files "tutorials/$c/validation/*.png")" ] || missing="$missing $c"
done
[ -z "$missing" ] && pass status_pictures \
    || fail status_pictures "no committed validation/*.png in:$missing"
exit $((fails > 0))
