#!/usr/bin/env bash
# choices.sh — the model choices the dictionaries' comments list agree with
# the programs' registries (src/core/select.h: every model choice is a
# table, printed by `mpsFluid -listModels` and `demSolid -listModels` as
# "FILE KEY NAME" lines).
#
# For an entry `key value; // a (...) | b: ... | c` of a registered key
# (also commented out, `//   key value; // ...`, as the references show
# optional dictionaries), with the comment's continuation lines:
#   - the value is a registered name;
#   - every choice the comment lists exists in the registry: the comment
#     is split at '|' (parenthesised text and |x| norms removed first),
#     and each piece names the entry's value or starts with a choice;
#   - every registered name appears in the comment (in a tutorial, when
#     the comment is a '|' list; not for the preconditioner, whose list
#     there is the one of the case's solver).
# Checked in the reference dictionaries (applications/**/*.reference,
# against the registry of their program) and in every tutorial's and the
# root case's dictionary of a registered file. Prints PASS name /
# FAIL name: reason.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$ROOT" || exit 1
TMP=$(mktemp -d); trap 'rm -rf "$TMP"' EXIT
status=0

for p in mpsFluid demSolid mlpgFluid isphSediment; do
    if ! bin/$p -listModels > "$TMP/$p.out" 2>&1; then
        echo "FAIL listModels_$p: bin/$p -listModels exited non-zero"; exit 1
    fi
    grep -E '^(system|constant)/[A-Za-z]+ [A-Za-z/]+ [A-Za-z0-9_]+$' \
        "$TMP/$p.out" > "$TMP/$p.reg"
    if [ -s "$TMP/$p.reg" ]; then echo "PASS listModels_$p"
    else echo "FAIL listModels_$p: no FILE KEY NAME lines"; exit 1; fi
done
sort -u "$TMP/mpsFluid.reg" "$TMP/demSolid.reg" "$TMP/mlpgFluid.reg" "$TMP/isphSediment.reg" > "$TMP/all.reg"

# check REGISTRY DICT LABEL FILE_FILTER REVERSE: one PASS/FAIL line per
# registered entry found in DICT ("*" filter: every registered file).
check()
{
    awk -v label="$3" -v only="$4" -v reverse="$5" '
    BEGIN { partial["preconditioner"] = 1 }
    function strip(s,   out, depth, i, c) {
        gsub(/\|[^| ]+\|/, " ", s)          # norms |F_n|
        out = ""; depth = 0
        for (i = 1; i <= length(s); i++) {
            c = substr(s, i, 1)
            if (c == "(") depth++
            else if (c == ")") { if (depth > 0) depth-- }
            else if (c == "|") { out = out c; depth = 0 }
            else if (depth == 0) out = out c
        }
        return out
    }
    function finish(   n, pieces, i, t, m, first, has, bad, miss, k, nm) {
        if (!key) return
        n = split(strip(text), pieces, "|")
        bad = ""
        if (!((key SUBSEP value) in reg))
            bad = "value " value " is not registered"
        for (i = 1; i <= n && n > 1; i++) {
            m = split(pieces[i], t, /[^A-Za-z0-9_]+/)
            first = ""; has = 0
            for (k = 1; k <= m; k++) {
                if (t[k] == "") continue
                if (first == "") first = t[k]
                if (t[k] == value) has = 1
            }
            if (!has && first != "" && !((key SUBSEP first) in reg))
                bad = bad (bad ? "; " : "") "lists " first \
                      ", not a registered " key
        }
        if (reverse || (n > 1 && !(key in partial))) {
            miss = ""
            for (k = 1; k <= nnames[key]; k++) {
                nm = names[key, k]
                if (!match(" " text " ", "[^A-Za-z0-9_]" nm "[^A-Za-z0-9_]"))
                    miss = miss " " nm
            }
            if (miss) bad = bad (bad ? "; " : "") "does not list" miss
        }
        name = label ":" line0 ":" key
        if (bad) { print "FAIL " name ": " bad; fails++ }
        else print "PASS " name
        key = ""
    }
    FNR == NR {
        if (only != "*" && $1 != only) next
        leaf = $2; sub(/.*\//, "", leaf)
        if (!((leaf SUBSEP $3) in reg)) names[leaf, ++nnames[leaf]] = $3
        reg[leaf, $3] = 1; known[leaf] = 1
        next
    }
    {
        if (key) {
            cont = commented ? /^\/\/[ \t]+\/\// : /^[ \t][ \t][ \t][ \t][ \t][ \t][ \t][ \t]*\/\//
            rest = $0; sub(/^[ \t]*(\/\/)?[ \t]*/, "", rest)
            if (cont && rest !~ /^[A-Za-z][A-Za-z0-9_]*[ \t]+[^ \t;]+;/) {
                c = $0; sub(/^[ \t]*(\/\/[ \t]*)?\/\//, "", c)
                text = text " " c; next
            }
            finish()
        }
        if (match($0, /^[ \t]*(\/\/[ \t]*)?[A-Za-z][A-Za-z0-9_]*[ \t]+[A-Za-z0-9_]+[ \t]*;/)) {
            e = substr($0, 1, RLENGTH); c = substr($0, RLENGTH + 1)
            commented = e ~ /^[ \t]*\/\//
            sub(/^[ \t]*(\/\/[ \t]*)?/, "", e); sub(/[ \t]*;$/, "", e)
            split(e, kv, /[ \t]+/)
            if (!(kv[1] in known) || c !~ /^[ \t]*\/\//) next
            sub(/^[ \t]*\/\//, "", c)
            key = kv[1]; value = kv[2]; text = c; line0 = FNR
        }
    }
    END { finish(); exit fails > 0 }' "$1" "$2"
}

for p in mpsFluid demSolid mlpgFluid isphSediment; do
    ref=$(find applications -name "$p.reference")
    check "$TMP/$p.reg" "$ref" "${ref##*/}" "*" 1 || status=1
done
for f in $(cut -d' ' -f1 "$TMP/all.reg" | sort -u); do
    for d in $f tutorials/*/*/$f; do
        [ -f "$d" ] || continue
        check "$TMP/all.reg" "$d" "$d" "$f" 0 || status=1
    done
done
exit $status
