#!/bin/bash
# standalone.sh — the repository stands alone: a clone with nothing beside
# it has everything its code, tests, tutorials and notes read or cite.
#   standalone_reads  no tracked file outside Markdown reads a data folder
#                     beside the clone (reference data live in data/)
#   standalone_cites  no tracked file cites the founders' planning notes,
#                     which are not part of the repository (the names in
#                     the pattern below); the theory and design notes are
#                     doc/theory.md, doc/design.md and doc/libraries.md
#   standalone_data   every folder of data/ has a README.md
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
git -C "$ROOT" rev-parse --git-dir > /dev/null 2>&1 \
    || { fail standalone "$ROOT is not a git checkout"; exit 1; }
cd "$ROOT" || exit 1
self=test/cases/standalone.sh

hits=$(git grep -nE '\.\./shared|shared/data' -- ':!*.md' ":!$self")
[ -z "$hits" ] && pass standalone_reads \
    || fail standalone_reads "$(echo "$hits" | head -n 5 | tr '\n' ' ')"

hits=$(git grep -nE '(METHODS|DESIGN|STYLE|toolchain)\.md' -- ":!$self")
[ -z "$hits" ] && pass standalone_cites \
    || fail standalone_cites "$(echo "$hits" | wc -l) lines, e.g. $(echo "$hits" | head -n 3 | tr '\n' ' ')"

bad=""
for d in data/*/; do [ -s "$d/README.md" ] || bad="$bad $d"; done
[ -d data ] && [ -z "$bad" ] && pass standalone_data \
    || fail standalone_data "no README.md in:${bad:- data/ missing}"
exit $((fails > 0))
