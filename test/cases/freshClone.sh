#!/bin/bash
# freshClone.sh — what a new user does first: clone the repository into an
# empty folder (nothing beside the clone, no build/) and type ./Allrun.
#   fresh_allrun   ./Allrun exits 0 (it installs what is missing, builds,
#                  runs the root case) within 15 min
#   fresh_summary  its summary names both fronts in mm, the water front
#                  between 150 and 205 mm and the sediment front between
#                  60 and 200 mm at t = 0.200 s (measured 199.3 and 119.5)
#   fresh_outputs  fronts.png, fluid.pvd, dem.pvd and the 0.2 time directory
#                  with both clouds exist
#   fresh_rerun    a second ./Allrun in the same clone exits 0 and does not
#                  run the solvers again (runApplication's log guard)
# Clones HEAD: what is tested is what is committed.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }

git -C "$ROOT" rev-parse --git-dir > /dev/null 2>&1 \
    || { fail fresh_clone "$ROOT is not a git checkout"; exit 1; }
git clone -q "$ROOT" "$TMP/mpsdem" || { fail fresh_clone "git clone failed"; exit 1; }
c="$TMP/mpsdem"
[ ! -e "$c/build" ] || { fail fresh_clone "the clone has a build/"; exit 1; }

s=$(date +%s)
if (cd "$c" && timeout 900 ./Allrun > "$TMP/log.Allrun" 2>&1); then
    pass fresh_allrun
else
    fail fresh_allrun "exit status $? after $(( $(date +%s) - s )) s: $(tail -n 5 "$TMP/log.Allrun" | tr '\n' ' ')"
    exit 1
fi
echo "    ./Allrun on a fresh clone took $(( $(date +%s) - s )) s"
sed -n '/^Summary/,$p' "$TMP/log.Allrun" | sed 's/^/    /'

w=$(sed -n 's/^ *water front *x = \([0-9.]*\) mm.*/\1/p' "$TMP/log.Allrun")
d=$(sed -n 's/^ *sediment front *x = \([0-9.]*\) mm.*/\1/p' "$TMP/log.Allrun")
if grep -q '^Summary at t = 0.200 s' "$TMP/log.Allrun" && [ -n "$w" ] && [ -n "$d" ] \
   && awk -v w="$w" -v d="$d" 'BEGIN { exit !(w >= 150 && w <= 205 && d >= 60 && d <= 200) }'; then
    pass fresh_summary
else
    fail fresh_summary "summary line missing or fronts out of range (water '$w' mm, sediment '$d' mm)"
fi

missing=""
for f in fronts.png fluid.pvd dem.pvd 0.2/fluid.vtu 0.2/dem.vtu; do
    [ -s "$c/$f" ] || missing="$missing $f"
done
[ -z "$missing" ] && pass fresh_outputs || fail fresh_outputs "missing:$missing"

if (cd "$c" && timeout 300 ./Allrun > "$TMP/log.Allrun2" 2>&1) \
   && grep -q 'already run' "$TMP/log.Allrun2" && ! grep -q '^Running mpsFluid' "$TMP/log.Allrun2"; then
    pass fresh_rerun
else
    fail fresh_rerun "$(tail -n 3 "$TMP/log.Allrun2" | tr '\n' ' ')"
fi
exit $((fails > 0))
