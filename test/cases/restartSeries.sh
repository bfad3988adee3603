#!/bin/bash
# restartSeries.sh — a validation script joins the function objects'
# output of a restarted run (postProcessing/<name>/<startTime>/) in time
# order, each start directory up to the next one's start: a run restarted
# from an earlier write repeats the times after it, and those rows must
# come from the restart, once.
#   restart_series_join  squareColumn's validation/compare.sh on a case
#                        with start directories 0 (to 0.6 s) and 0.4
#                        (from 0.41 s): validation/series.dat has strictly
#                        increasing times, the restart's values after 0.4 s
#                        and the first run's before
#   restart_series_tool  bin/tools/foJoin, which every validation script
#                        uses, on the same case with a third start
#                        directory (2.5, from 2.51 s) and a fourth that
#                        holds no file: strictly increasing times, each
#                        run's rows up to the next start
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
fails=0
pass() { echo "PASS $1"; }
fail() { echo "FAIL $1: $2"; fails=$((fails + 1)); }
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT

# one function object's file: times from $3 to $4 every 0.01 s, value $5
series() {
    mkdir -p "$TMP/case/postProcessing/$1/$3"
    awk -v a="$3" -v b="$4" -v v="$5" -v cols="$6" 'BEGIN { print "# header"
        for (k = 0; a + 0.01 * k <= b + 1e-9; k++) { t = a + 0.01 * k; if (t == 0) continue
            printf "%g", t; for (c = 1; c <= cols; c++) printf " %s", (c == 1 ? v + t : 0); printf "\n" } }' \
        > "$TMP/case/postProcessing/$1/$3/$2"
}
for start in 0 0.4; do
    end=$([ "$start" = 0 ] && echo 0.6 || echo 3)
    first=$([ "$start" = 0 ] && echo 0 || echo 0.41)
    v=$([ "$start" = 0 ] && echo 100 || echo 200)
    series load forces.dat "$start" "$end" "$v" 3
    series P1 probes.dat "$start" "$end" "$v" 1
    series velocity probes.dat "$start" "$end" "$v" 3
    series H1 waveGauges.dat "$start" "$end" "$v" 1
    series waterFront front.dat "$start" "$end" "$v" 1
    [ "$first" = 0 ] || for f in "$TMP"/case/postProcessing/*/0.4/*.dat; do
        awk '/^#/ || $1 >= 0.41' "$f" > "$f.x" && mv "$f.x" "$f"; done
done
if ! MPSDEM_DIR="$ROOT" sh "$ROOT/tutorials/mpsFluid/squareColumn/validation/compare.sh" "$TMP/case" > "$TMP/out" 2>&1; then
    fail restart_series_join "compare.sh failed: $(tail -n 3 "$TMP/out" | tr '\n' ' ')"
else
    bad=$(awk '!/^#/ { n++; if (n > 1 && $1 <= p) print "time " $1 " after " p
                      if ($1 <= 0.4 + 1e-9 && $2 != 100 + $1) print "t " $1 ": F " $2 " (first run: " 100 + $1 ")"
                      if ($1 > 0.405 && $2 != 200 + $1) print "t " $1 ": F " $2 " (restart: " 200 + $1 ")"; p = $1 }
              END { if (n != 300) print n " rows (300 expected)" }' "$TMP/case/validation/series.dat")
    [ -z "$bad" ] && pass restart_series_join || fail restart_series_join "$(echo "$bad" | head -n 3 | tr '\n' ' ')"
fi
series load forces.dat 2.5 4 300 3
awk '/^#/ || $1 >= 2.51' "$TMP/case/postProcessing/load/2.5/forces.dat" > "$TMP/f" \
    && mv "$TMP/f" "$TMP/case/postProcessing/load/2.5/forces.dat"
mkdir -p "$TMP/case/postProcessing/load/3.5"
"$ROOT/bin/tools/foJoin" "$TMP/case/postProcessing/load" forces.dat > "$TMP/joined"
bad=$(awk '{ n++; if (n > 1 && $1 <= p) print "time " $1 " after " p
             v = $1 <= 0.4 + 1e-9 ? 100 : $1 <= 2.5 + 1e-9 ? 200 : 300
             if ($2 != v + $1) print "t " $1 ": " $2 " (expected " v + $1 ")"; p = $1 }
           END { if (n != 400) print n " rows (400 expected)" }' "$TMP/joined")
[ -z "$bad" ] && pass restart_series_tool || fail restart_series_tool "$(echo "$bad" | head -n 3 | tr '\n' ' ')"
exit $((fails > 0))
