#!/usr/bin/env bash
# isph.sh — isphSediment on its tutorial (tutorials/isphSediment; doc/
# theory.md S, checks E.4; ~40 s):
#   neutral buoyancy, cases 1a (alpha_s = 0.1) and 1b (alpha_s = 0.5 (1 -
#     y)), dl = 0.02 m, 1.5 s (E4-04): pressure L2 against rho g (H - y)
#     < 1 % (measured 2e-12 / 8e-13: hydrostatics is exact), largest
#     displacement < 0.1 dl (1e-11 dl), |alpha_s - alpha_s0| off the free
#     surface < 1e-4 (1e-13); the free-surface detector (E4-10) flags the
#     top row alone, 49 particles, at every step
#   settling (tutorial settling at dl = 0.02 m, 5 s; E4-06, E4-07): peak
#     of the row-mean alpha_s within dl/2 of (5.50)'s 0.2206 m (measured
#     -0.0008 m), L_inf <= 10 % of alpha_s0 (3.2 %), volume within 1 %
#     (+0.32 %)
#   the raised-cosine start profile (5.51) of the settling test: alpha_s
#     of the water particles at y = 0.1, 0.2, 0.3, 0.5 m is 0, 5e-4, 1e-3,
#     0 (1e-9) after one step
#   bad input: an unknown kernel (file:line, did you mean), a smoothing
#     length whose support misses the free-surface detector's reach, no
#     constant/sedimentProperties, dummy particles, alpha_s above alphaMax:
#     non-zero exit, a message naming the cause, no time directory written
NAME=isph; . "$(dirname "$0")/lib/case.sh"
need_bins isphSediment genParticles vtuInfo dictTool
export MPSDEM_DIR="$ROOT"
NB="$ROOT/tutorials/isphSediment/neutralBuoyancy"
setcase() { rm -rf "$TMP/$1"; cp -r "$2" "$TMP/$1"; c="$TMP/$1"; }
set_entry() { "$ROOT/bin/dictTool" -case "$c" "$1" -set "$2=$3" >/dev/null; }

for k in 1a 1b; do
    setcase "neutral$k" "$NB"
    if out=$(cd "$c" && ./Allrun "$k" 2>&1); then
        r=$(echo "$out" | tail -n 1)
        echo "    $k: $r"
        log="$c/log.isphSediment"; [ "$k" = 1a ] || log="$c/1b/log.isphSediment"
        surf=$(awk '/^Time/ { for (k = 1; k <= NF; k++) if ($k == "surface") print $(k + 1) }' "$log" | sort -u | tr '\n' ' ')
        echo "$r" | awk '{ gsub(/[(),]/, " "); for (k = 1; k <= NF; k++) { if ($k == "L2") l2 = $(k + 1)
                             if ($k == "dl") d = $(k - 1); if ($k == "surface") a = $(k + 1) } }
                         END { exit !(l2 != "" && l2 < 0.01 && d < 0.1 && a < 1e-4) }' \
            && pass "isph_neutral_$k" || fail "isph_neutral_$k" "$r"
        [ "$surf" = "49 " ] && pass "isph_surface_$k" || fail "isph_surface_$k" "surface counts over the run: $surf(49 expected)"
    else
        fail "isph_neutral_$k" "$(echo "$out" | tail -n 2 | tr '\n' ' ')"
    fi
done

# --- settling (tutorials/isphSediment/settling at dl = 0.02 m) ---
setcase settling "$ROOT/tutorials/isphSediment/settling"
rm -f "$c"/validation/profile_dl*.dat
if out=$(cd "$c" && ./Allrun 0.02 2>&1); then
    echo "$out" | tail -n 3 | sed 's/^/    /'
    echo "$out" | awk '/^peak/ { d = $13; if (d < 0) d = -d } /^Linf/ { l = $2 } /^volume/ { v = $(NF - 1); if (v < 0) v = -v }
                       END { exit !(d != "" && d <= 0.01 && l != "" && l <= 0.1 && v != "" && v < 1) }' \
        && pass isph_settling || fail isph_settling "$(echo "$out" | tail -n 3 | tr '\n' ' ')"
else
    fail isph_settling "$(echo "$out" | tail -n 2 | tr '\n' ' ')"
fi

# --- the raised-cosine start profile (5.51) ---
setcase cosine "$NB"
set_entry system/controlDict endTime 0.001
set_entry system/controlDict writeInterval 0.001
"$ROOT/bin/dictTool" -case "$c" system/isphSolution -new -set alphaSediment/type=cosine \
    -set alphaSediment/peak=1e-3 -set "alphaSediment/direction=(0 1 0)" -set alphaSediment/from=0.1 \
    -set alphaSediment/to=0.5 > /dev/null
sed -i '/^ *value /d; /^ *gradient /d; /^ *origin /d' "$c/system/isphSolution"
if (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 && "$ROOT/bin/isphSediment" > log.isphSediment 2>&1); then
    r=$("$ROOT/bin/vtuInfo" -dump "$c/0.001/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 && $1 > 0.49 && $1 < 0.51 { for (q = 1; q <= 4; q++) { y = q == 1 ? 0.1 : q == 2 ? 0.2 : q == 3 ? 0.3 : 0.5
              w = q == 1 ? 0 : q == 2 ? 5e-4 : q == 3 ? 1e-3 : 0
              d = $2 - y; if (d < 0) d = -d; if (d < 0.005) { e = $c["alpha.sediment"] - w; if (e < 0) e = -e; if (e > m) m = e; n++ } } }
        END { printf "%d %g", n, m }')
    set -- $r
    [ "$1" = 4 ] && awk -v e="$2" 'BEGIN { exit !(e < 1e-9) }' && pass isph_cosine_profile \
        || fail isph_cosine_profile "rows found $1, largest error $2"
else
    fail isph_cosine_profile "$(grep -h -A1 FATAL "$c"/log.* | tail -1)"
fi

# --- bad input ---
bad() { # name expected-regexp
    local out
    out=$(cd "$c" && "$ROOT/bin/isphSediment" 2>&1); local rc=$?
    local extra=$(cd "$c" && ls -d [0-9]* | grep -v '^0$' | tr '\n' ' ')
    if [ $rc -ne 0 ] && echo "$out" | grep -qE "$2" && [ -z "$extra" ]; then
        pass "isph_bad_$1"
    else
        fail "isph_bad_$1" "rc $rc, time dirs '$extra', message: $(echo "$out" | grep -A1 FATAL | tail -1)"
    fi
}
setcase bad "$NB"
sed -i 's/^dp .*/dp 0.1;/' "$c/system/particleDict"
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
set_entry system/isphSchemes kernel wendland
bad kernel "system/isphSchemes:[0-9]+.*wendland.*did you mean 'wendlandC2'"
set_entry system/isphSchemes kernel wendlandC2
set_entry system/isphSchemes smoothingLength 1.2
bad smoothingLength "system/isphSchemes:[0-9]+.*smoothingLength.*2.5 dl"
set_entry system/isphSchemes smoothingLength 1.3
mv "$c/constant/sedimentProperties" "$c/constant/sediment.off"
bad sedimentProperties "constant/sedimentProperties"
mv "$c/constant/sediment.off" "$c/constant/sedimentProperties"
set_entry system/isphSolution alphaSediment/value 0.7
bad alphaMax "alpha.sediment 0.7 outside \[0, alphaMax = 0.606\]"
set_entry system/isphSolution alphaSediment/value 0.1
set_entry system/particleDict wallLayers 2
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
bad dummy "0/fluid.vtu: particle [0-9]+ is a dummy particle .*wallLayers 1"
exit $((fails > 0))
