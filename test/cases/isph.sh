#!/usr/bin/env bash
# isph.sh — isphSediment on its tutorials (tutorials/isphSediment; doc/
# theory.md S, checks E.4; ~130 s):
#   neutral buoyancy, cases 1a (alpha_s = 0.1) and 1b (alpha_s = 0.5 (1 -
#     y)), dl = 0.02 m, 1.5 s (E4-04): pressure L2 against rho g (H - y)
#     < 1 % (measured 2e-12 / 8e-13: hydrostatics is exact), largest
#     displacement < 0.1 dl (1e-11 dl), |alpha_s - alpha_s0| off the free
#     surface < 1e-4 (1e-13), the water particles' volumes (5.34) sum to
#     (1 - dl) x 1 m^2 to 1e-9 (E4-03: the wall particles stand on the
#     walls); the free-surface detector (E4-10) flags the
#     top row alone, 49 particles, at every step; case 1b with d = 0.15
#     mm (where the explicit drag blows up) and the semi-implicit drag
#     (S0-07) likewise
#   settling (tutorial settling at dl = 0.02 m, 5 s; E4-06, E4-07): peak
#     of the row-mean alpha_s within dl/2 of (5.50)'s 0.2206 m (measured
#     -0.0008 m), L_inf <= 10 % of alpha_s0 (3.2 %), volume within 1 %
#     (+0.32 %), pressure L2 against the hydrostatic plus the suspended
#     excess < 1 % (E4-08: 1.2e-4)
#   settling with `sedimentFlux conservative` (S0-09): the same E4-06,
#     E4-07 gates (measured -0.0008 m, 3.3 %, +0.32 %)
#   settling with `sedimentFlux upwind` (S0-09): sum alpha_s V from 1 to
#     5 s within 1e-6 (exact to the printed digits), no alpha_s clipped
#   the box start profile (S0-10): sum alpha_s V = value x area to 1e-9,
#     with the box's edges inside particle cells; max below min refused
#   the raised-cosine start profile (5.51) of the settling test: alpha_s
#     of the water particles at y = 0.1, 0.2, 0.3, 0.5 m is 0, 5e-4, 1e-3,
#     0 (1e-9) after one step
#   terminal slip (E4-05): a suspension of alpha_s = 1e-5, d = 0.15,
#     0.8, 1.3, 5 mm, rho_s = 2650, 0.4 s from rest: the mean |u_s - u_f|
#     in the middle of the tank within 0.5 % of the thesis's omega_s
#     (measured -0.09, -0.08, -0.07, -0.06 %), explicit and semi-implicit
#     drag
#   the options for fast flows (wall dummyLayers, freeSurface
#     positionDivergence, shifting, collision, clipNegativePressure,
#     velocitySmoothing, volumeRelaxation; S0-13 to S0-19) on case 1a with
#     wallLayers 3, once with the batch settling's isphSchemes (shepard,
#     volumeRelaxation 0.05, semiImplicit, upwind) and once with
#     velocitySmoothing biharmonic, velocitySmoothingRegion freeSurface
#     and sedimentFlux muscl: still water
#     stays at rest (pressure L2 < 1e-9, displacement < 1e-6 dl; measured
#     1e-12)
#   batch settling (tutorials/isphSediment/batchSettling) at dl = 0.02 m,
#     alpha_s0 = 0.1, 6 s (E4-09): the interface's descent within 10 % of
#     the model-consistent alpha_f w = 1.030 cm/s (measured -5.1 %; the
#     tutorial's dl = 0.01 m: -2.8 %), the bulk's slip u_s - u_f within
#     5 % of w = 1.145 cm/s, the sediment volume kept (1e-9)
#   the dam break (tutorials/isphSediment/damBreak) at a/10, 0.6 s: RMS of
#     the front < 0.35 (measured 0.27), of the column height < 0.05 (0.03)
#   the sand dumping case 2 (tutorials/isphSediment/sandDumping) at dl =
#     0.02 m, 1 s: front velocity within 40 % of omega_s (E4-12; 0.537
#     m/s), sediment volume kept (0)
#   bad input: an unknown kernel (file:line, did you mean), a smoothing
#     length whose support misses the free-surface detector's reach, no
#     constant/sedimentProperties, dummy particles with wall neumann, wall
#     dummyLayers without them, an unknown wall scheme, alpha_s above
#     alphaMax, volumeRelaxation without dummy layers: non-zero exit, a
#     message naming the cause, no time directory written
NAME=isph; . "$(dirname "$0")/lib/case.sh"
need_bins isphSediment genParticles vtuInfo dictTool
export MPSDEM_DIR="$ROOT"
NB="$ROOT/tutorials/isphSediment/neutralBuoyancy"
setcase() { rm -rf "$TMP/$1"; cp -r "$2" "$TMP/$1"; c="$TMP/$1"; }
set_entry() { "$ROOT/bin/dictTool" -case "$c" "$1" -new -set "$2=$3" >/dev/null; }

bad() { expect_refusal "isph_bad_$1" isphSediment "$2"; } # name expected-regexp
# allrun NAME ARGS...: ./Allrun ARGS in $c, its output in $out; on failure
# NAME fails with the output's last lines (returns 1)
allrun() {
    local name=$1; shift
    out=$(cd "$c" && ./Allrun "$@" 2>&1) && return 0
    fail "$name" "$(echo "$out" | tail -n 2 | tr '\n' ' ')"
    return 1
}
# e404 LINE L2 D A [V]: validation/check.sh's LINE (neutralBuoyancy) has
# pressure L2 < L2, displacement < D dl, alpha_s change off the surface
# < A and, with V, sum V within V of the (1 - dl) m^2 of E4-03
e404() {
    echo "$1" | awk -v L="$2" -v D="$3" -v A="$4" -v V="${5:-}" '
        { gsub(/[(),]/, " "); for (k = 1; k <= NF; k++) { if ($k == "L2") l2 = $(k + 1)
              if ($k == "dl") d = $(k - 1); if ($k == "surface") a = $(k + 1); if ($k == "V") v = $(k + 1) } }
        END { e = v - 0.98; if (e < 0) e = -e
              exit !(l2 != "" && l2 < L && d < D && a < A && (V == "" || (v != "" && e < V))) }'
}
for k in 1a 1b; do
    setcase "neutral$k" "$NB"
    if allrun "isph_neutral_$k" "$k"; then
        r=$(echo "$out" | tail -n 1)
        echo "    $k: $r"
        log="$c/log.isphSediment"; [ "$k" = 1a ] || log="$c/1b/log.isphSediment"
        surf=$(awk '/^Time/ { for (k = 1; k <= NF; k++) if ($k == "surface") print $(k + 1) }' "$log" | sort -u | tr '\n' ' ')
        e404 "$r" 0.01 0.1 1e-4 1e-9 && pass "isph_neutral_$k" || fail "isph_neutral_$k" "$r"
        [ "$surf" = "49 " ] && pass "isph_surface_$k" || fail "isph_surface_$k" "surface counts over the run: $surf(49 expected)"
    fi
done

# --- case 1b with fine grains (d = 0.15 mm: dt gamma/rho_s = 6.4 at the
# bottom, the explicit drag blows up in the second step) and the
# semi-implicit drag (S0-07): still water stays still ---
setcase neutral1b_fine "$NB"
set_entry constant/sedimentProperties d 0.15e-3
set_entry system/isphSchemes drag semiImplicit
if allrun isph_neutral_1b_semiImplicit 1b; then
    r=$(echo "$out" | tail -n 1)
    echo "    1b, d = 0.15 mm, semiImplicit: $r"
    e404 "$r" 0.01 0.1 1e-4 && pass isph_neutral_1b_semiImplicit || fail isph_neutral_1b_semiImplicit "$r"
fi

# --- settling (tutorials/isphSediment/settling at dl = 0.02 m) with each
# sediment flux (S0-09); settling NAME FLUX GATE: GATE an awk program on
# the tutorial's output, with clip = the particles clipped over the run ---
settling() {
    setcase "$1" "$ROOT/tutorials/isphSediment/settling"
    rm -f "$c"/validation/profile_dl*.dat
    set_entry system/isphSchemes sedimentFlux "$2"
    if allrun "$1" 0.02; then
        echo "$out" | tail -n 4 | sed "s/^/    $2: /"
        local clip=$(awk '/^Time/ { for (k = 1; k < NF; k++) if ($k == "clipped") n = $(k + 1) } END { print n }' "$c/dl0.02/log.isphSediment")
        echo "$out" | awk -v clip="$clip" "$3" && pass "$1" \
            || fail "$1" "$(echo "$out" | tail -n 4 | tr '\n' ' '), clipped $clip"
    fi
}
e406='/^peak/ { d = $13; if (d < 0) d = -d } /^Linf/ { l = $2 } /^volume/ { v = $(NF - 1); if (v < 0) v = -v }
      /^pressure L2/ { p = $3 }'
settling isph_settling advective "$e406"'
    END { exit !(d != "" && d <= 0.01 && l != "" && l <= 0.1 && v != "" && v < 1 && p != "" && p < 0.01) }'
# sediment volume to round-off, alpha_s never clipped
settling isph_settling_upwind_volume upwind '/^volume/ { split($0, f, " "); v0 = f[2]; v1 = f[8] }
    END { e = (v1 - v0) / v0; if (e < 0) e = -e; exit !(v0 > 0 && e < 1e-6 && clip == 0) }'
# E4-06 and E4-07 as with the advective flux
settling isph_settling_conservative conservative "$e406"'
    END { exit !(d != "" && d <= 0.01 && l != "" && l <= 0.1 && v != "" && v < 1) }'

# --- the box start profile (S0-10): sum alpha_s V = value x the box's area
# (0.5 x 0.185 m x 0.27 m, its edges inside particle cells) ---
setcase box "$NB"
set_entry system/controlDict endTime 0.001
set_entry system/controlDict writeInterval 0.001
"$ROOT/bin/dictTool" -case "$c" system/isphSolution -new -set alphaSediment/type=box \
    -set alphaSediment/value=0.5 -set "alphaSediment/min=(0.405 0.5 0)" -set "alphaSediment/max=(0.59 0.77 0)" > /dev/null
sed -i '/^ *gradient /d; /^ *origin /d' "$c/system/isphSolution"
if (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 && "$ROOT/bin/isphSediment" > log.isphSediment 2>&1); then
    v=$("$ROOT/bin/vtuInfo" -dump "$c/0.001/fluid.vtu" | awk '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
        $1 ~ /^[-0-9.]/ && $c["type"] == 0 { s += $c["alpha.sediment"] * $c["volume"] } END { printf "%.12g", s }')
    echo "    box: sum alpha_s V = $v m^2 (0.024975)"
    awk -v v="$v" 'BEGIN { e = v / 0.024975 - 1; if (e < 0) e = -e; exit !(e < 1e-9) }' \
        && pass isph_box_profile || fail isph_box_profile "sum alpha_s V = $v, 0.024975 expected"
else
    fail isph_box_profile "$(grep -h -A1 FATAL "$c"/log.* | tail -1)"
fi
set_entry system/isphSolution "alphaSediment/max" "(0.3 0.77 0)"
rm -rf "$c/0.001"
bad box_bounds "system/isphSolution:[0-9]+.*max must exceed min"

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

# --- E4-05: terminal slip of a dilute suspension (alpha_s = 1e-5) ---
# rho_s = 2650, 0.4 s from rest at dl = 0.05 m; the mean |u_s - u_f| of
# the water particles in the middle of the tank (x 0.33-0.67, y 0.43-0.67
# m, far from the walls) against the thesis's omega_s (Table 1; 5.12-5.13
# at alpha_f -> 1, g = 9.8)
setcase slip "$NB"
sed -i 's/^dp .*/dp 0.05;/' "$c/system/particleDict"
set_entry constant/sedimentProperties rho 2650
set_entry system/isphSolution alphaSediment/value 1e-5
set_entry system/controlDict endTime 0.4
set_entry system/controlDict writeInterval 0.4
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
for drag in explicit semiImplicit; do
set_entry system/isphSchemes drag "$drag"
for p in "0.15e-3 0.01590" "0.8e-3 0.1260" "1.3e-3 0.1961" "5e-3 0.4952"; do
    set -- $p
    rm -rf "$c"/0.4 "$c"/log.isphSediment
    set_entry constant/sedimentProperties d "$1"
    if (cd "$c" && "$ROOT/bin/isphSediment" > log.isphSediment 2>&1); then
        r=$("$ROOT/bin/vtuInfo" -dump "$c/0.4/fluid.vtu" | awk -v w="$2" '/^# x/ { for (k = 2; k <= NF; k++) c[$k] = k - 1; next }
            $1 ~ /^[-0-9.]/ && $c["type"] == 0 && $1 > 0.325 && $1 < 0.675 && $2 > 0.425 && $2 < 0.675 {
                s += sqrt(($c["U.sediment_0"] - $c["velocity_0"])^2 + ($c["U.sediment_1"] - $c["velocity_1"])^2); n++ }
            END { if (n) printf "%d %.5g %.3f", n, s / n, 100 * (s / n - w) / w }')
        set -- $1 $2 $r
        echo "    E4-05 $drag, d = $1 m: slip $4 m/s over $3 particles, omega_s $2 m/s: $5 %"
        awk -v n="$3" -v e="$5" 'BEGIN { exit !(n > 20 && e < 0.5 && e > -0.5) }' \
            && pass "isph_terminal_slip_${drag}_$1" || fail "isph_terminal_slip_${drag}_$1" "slip $4 m/s, omega_s $2: $5 %"
    else
        fail "isph_terminal_slip_${drag}_$1" "$(grep -A1 FATAL "$c/log.isphSediment" | tail -1)"
    fi
done
done

# --- the options for fast flows (S0-13 to S0-17) keep still water at rest:
# case 1a with the dam break's isphSchemes and wallLayers 3, the E4-04
# gates and the same exactness (measured 1e-12) ---
DB="$ROOT/tutorials/isphSediment/damBreak"
BS="$ROOT/tutorials/isphSediment/batchSettling"
# stillcase NAME: case 1a in NAME with wallLayers 3 and the batch
# settling's isphSchemes
stillcase() {
    setcase "$1" "$NB"
    set_entry system/particleDict wallLayers 3
    local k
    for k in drag sedimentFlux wall freeSurface shifting shiftingCoefficient collision clipNegativePressure velocitySmoothing volumeRelaxation; do
        set_entry system/isphSchemes "$k" "$("$ROOT/bin/dictTool" "$BS/system/isphSchemes" -entry "$k" | tr -d ';')"
    done
}
stillcase neutralDummy
if allrun isph_neutral_1a_dummyLayers 1a; then
    r=$(echo "$out" | tail -n 1)
    echo "    1a, batch-settling options: $r"
    e404 "$r" 1e-9 1e-6 1e-9 1e-9 && pass isph_neutral_1a_dummyLayers || fail isph_neutral_1a_dummyLayers "$r"
fi
stillcase neutralBiharmonic
set_entry system/isphSchemes velocitySmoothing biharmonic
set_entry system/isphSchemes velocitySmoothingRegion freeSurface
set_entry system/isphSchemes sedimentFlux muscl
if allrun isph_neutral_1a_biharmonic 1a; then
    r=$(echo "$out" | tail -n 1)
    echo "    1a, biharmonic smoothing at the surface, muscl flux: $r"
    e404 "$r" 1e-9 1e-6 1e-9 1e-9 && pass isph_neutral_1a_biharmonic || fail isph_neutral_1a_biharmonic "$r"
fi

# --- batch settling (tutorials/isphSediment/batchSettling) at dl = 0.02
# m, alpha_s0 = 0.1, 6 s (E4-09): the interface's descent within 10 % of
# the model-consistent alpha_f w (measured -5.1 %), the bulk's slip within
# 5 % of w, the sediment volume kept ---
setcase batchSettling "$BS"
set_entry system/particleDict dp 0.02
if allrun isph_batchSettling; then
    e=$(echo "$out" | awk '/interface descent/ { for (k = 1; k <= NF; k++) if ($k == "error") print $(k + 1) }')
    r=$(awk '/^# model/ { w = $(NF - 1) } !/^#/ && $1 >= 0.5 { s += ($4 - $5) / w; n++ } END { if (n) printf "%.4f", -s / n - 1 }' "$c/validation/series_alpha0.1.dat")
    v=$(for t in 0.25 6; do "$ROOT/bin/vtuInfo" -dump "$c/$t/fluid.vtu"; done 2>/dev/null | awk '/^# x/ { f++; next } $1 ~ /^[-0-9.]/ && $8 == 0 { s[f] += $14 * $18 } END { if (s[1] > 0) printf "%.2e", (s[2] - s[1]) / s[1] }')
    echo "    batch settling dl = 0.02 m: interface descent error $e %, bulk slip error $r, volume change $v"
    awk -v e="$e" -v r="$r" -v v="$v" 'BEGIN { if (e < 0) e = -e; if (r < 0) r = -r; if (v < 0) v = -v
        exit !(e != "" && r != "" && v != "" && e < 10 && r < 0.05 && v < 1e-9) }' \
        && pass isph_batchSettling || fail isph_batchSettling "interface error $e %, slip error $r, volume change $v"
fi

# --- the dam break (tutorials/isphSediment/damBreak) at a/10 (dl = 0.02
# m, dt = 1e-3 s), 0.6 s: it runs through the surge's arrival at the far
# wall, RMS of the front Z < 0.35 (measured 0.27) and of the column height
# H < 0.05 (0.03) against Martin & Moyce ---
setcase damBreak "$DB"
set_entry system/particleDict dp 0.02
set_entry system/controlDict deltaT 1e-3
if allrun isph_damBreak; then
    z=$(echo "$out" | awk '$1 == "rmsZ" { print $2 }'); h=$(echo "$out" | awk '$1 == "rmsH" { print $2 }')
    echo "    dam break a/10: rmsZ $z rmsH $h"
    awk -v z="$z" -v h="$h" 'BEGIN { exit !(z != "" && z < 0.35 && h < 0.05) }' \
        && pass isph_damBreak || fail isph_damBreak "rmsZ $z rmsH $h"
fi

# --- sand dumping (tutorials/isphSediment/sandDumping), case 2 (d = 5 mm)
# at dl = 0.02 m to 1 s: the cloud's front velocity omega_c averaged over
# 0.6-1 s within 40 % of the single grain's 0.4952 m/s (E4-12; measured
# 0.537 m/s, +8 %), the sediment volume sum alpha_s V kept to 1e-9 from
# the first written time, 0.05 s (muscl flux; measured 0; the block at
# alpha_sm is clipped in the first steps) ---
setcase sandDumping "$ROOT/tutorials/isphSediment/sandDumping"
set_entry system/particleDict dp 0.02
set_entry system/controlDict endTime 1
if allrun isph_sandDumping_case2 2; then
    r=$(awk '!/^#/ && $1 >= 0.6 && $1 <= 1.0001 { w += $4; n++ } !/^#/ { if (!v0) v0 = $6; dv = $6 / v0 - 1; if (dv < 0) dv = -dv; if (dv > e) e = dv }
             END { if (n) printf "%.4f %.2e", w / n, e }' "$c/validation/series_case2.dat")
    set -- $r
    echo "    sand dumping case 2, dl = 0.02 m: omega_c $1 m/s over 0.6-1 s (omega_s 0.4952), volume change $2"
    awk -v w="$1" -v e="$2" 'BEGIN { exit !(w != "" && w > 0.6 * 0.4952 && w < 1.4 * 0.4952 && e < 1e-9) }' \
        && pass isph_sandDumping_case2 || fail isph_sandDumping_case2 "omega_c $1, volume change $2"
fi

# --- bad input ---
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
bad dummy "system/isphSchemes.*0/fluid.vtu holds [0-9]+ dummy particles .*wall dummyLayers.*wallLayers 1"
set_entry system/particleDict wallLayers 1
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
set_entry system/isphSchemes wall dummyLayers
bad noDummy "system/isphSchemes:[0-9]+.*no dummy particles.*wallLayers 3"
set_entry system/isphSchemes wall dummy
bad wallName "system/isphSchemes:[0-9]+.*unknown wall scheme 'dummy'; valid: neumann dummyLayers"
set_entry system/isphSchemes wall neumann
set_entry system/isphSchemes volumeRelaxation 0.05
bad volumeRelaxation "system/isphSchemes:[0-9]+.*volumeRelaxation 0.05 needs .wall dummyLayers."
exit $((fails > 0))
