#!/usr/bin/env bash
# mpsSoil2D.sh — soil particles in mpsFluid (doc/theory.md K) on the
# tutorial tutorials/mpsFluid/soilLayerStill coarsened to dp = 10 mm
# (20 x 10 soil particles under 20 x 10 water, 548 with walls), 0.1 s:
#   run:       both soil models reach End; fluid.vtu holds phase (200 soil
#              particles) and acceleration
#   E5-02:     liquid model, probes in the soil (floor, mid-depth) and in the
#              water within 5 % of rho g (h_w - h_s) + rho_s g (h_s - y)
#              over 0.05-0.1 s (measured within 1 % at dp = 5 mm)
#   solid:     the layer stays put over 0.1 s (soil speeds < 2 % sqrt(g h));
#              E5-02 at dp = 5 mm over 0-1 s (soil and water pressure L2
#              < 5 %, displacement < 0.5 dp)
#   restart:   0 -> 0.1 s equals 0 -> 0.05 s + restart (the acceleration
#              of the last step is read back) to round-off
#   slope:     tutorials/mpsFluid/soilSlope as shipped: E5-03, the
#              deposit's angle within 5 deg of atan(mu), mu = 0.3, 0.577, 1
#   incline:   tutorials/mpsFluid/soilBlockIncline: E5-04, the middle of
#              the block at rest at 25 deg and sliding at 35 deg
#   mobile bed: tutorials/mpsFluid/damBreakMobileBed at dp = 10 mm, 0.3 s,
#              solid, liquid and the bed as water: soil and water past the
#              gate (x > 0.35 m), all 450 soil particles kept
#   phase:     function objects on one phase (volume, waveGauges, front
#              with phase soil / water) count and locate the right particles;
#              forces with phase soil / water split the floor's load
#   bad input: missing constant/soilProperties named; unknown soilModel
#              with "did you mean"; phase soil in a case without soil
NAME=mpsSoil2D; . "$(dirname "$0")/lib/case.sh"
need_bins mpsFluid genParticles vtuInfo dictTool
TUT="$ROOT/tutorials/mpsFluid/soilLayerStill"
setcase() {
    rm -rf "$TMP/$1"; cp -r "$TUT" "$TMP/$1"; c="$TMP/$1"
    "$ROOT/bin/dictTool" -case "$c" system/particleDict -set dp=0.01 > /dev/null
    "$ROOT/bin/dictTool" -case "$c" system/controlDict -set endTime=0.1 > /dev/null
    "$ROOT/bin/dictTool" -case "$c" system/controlDict -set writeInterval=0.05 > /dev/null
}
run() { (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1); }

# --- liquid model: E5-02 on the probes ---------------------------------------
setcase liquid
sed -i 's/^soilModel .*/soilModel liquid;/' "$c/constant/soilProperties"
# function objects on one phase (key phase): soil and water volumes, the
# top of the bed at x = 0.1 (waveGauges), the top soil row (front upwards)
fo() { "$ROOT/bin/dictTool" -case "$c" system/controlDict -new -set "functions/$1" > /dev/null; }
fo soilVol/type=volume; fo soilVol/phase=soil
fo waterVol/type=volume; fo waterVol/phase=water
fo bedTop/type=waveGauges; fo bedTop/phase=soil; fo "bedTop/gaugeLocations=(0.1)"
fo soilUp/type=front; fo soilUp/phase=soil; fo "soilUp/direction=(0 1 0)"
for ph in all soil water; do fo "load_$ph/type=forces"; fo "load_$ph/patches=(tank)"; fo "load_$ph/phase=$ph"; done
if run && grep -q '^End' "$c/log.mpsFluid"; then pass soil_liquid_run
else fail soil_liquid_run "$(grep -A2 FATAL "$c/log.mpsFluid" | head -3 | tr '\n' ' ')"; fi
# probes (0.1, 0.0025), (0.1, 0.05), (0.1, 0.15); h_s = 0.1, h_w = 0.2
got=$(awk '!/^#/ && $1 >= 0.05 { n++; for (k = 2; k <= 4; k++) s[k] += $k }
      END { e[2] = 981 + 1900 * 9.81 * 0.0975; e[3] = 981 + 1900 * 9.81 * 0.05; e[4] = 1000 * 9.81 * 0.05
            for (k = 2; k <= 4; k++) { r = s[k] / n / e[k] - 1; if (r < 0) r = -r; if (r > m) m = r }
            printf "%.4f", m }' "$c/postProcessing/soil/0/probes.dat" 2>/dev/null)
if [ -n "$got" ] && awk -v m="$got" 'BEGIN { exit !(m < 0.05) }'; then pass "soil_E5-02_liquid (largest probe error $got)"
else fail soil_E5-02_liquid "largest probe error '$got' (want < 0.05)"; fi

pp="$c/postProcessing"
got=$(for f in soilVol/0/volume.dat waterVol/0/volume.dat bedTop/0/waveGauges.dat soilUp/0/front.dat; do
          awk '!/^#/ { v = $2 } END { printf "%s ", v }' "$pp/$f" 2>/dev/null; done)
# 200 soil and 200 water particles; bed top 0.1 m (the top soil particle
# + dp/2) and the top soil centre 0.095 m, both within dp/2 after 0.1 s
if echo "$got" | awk '{ exit !($1 == 200 && $2 == 200 && $3 > 0.095 && $3 < 0.105 && $4 > 0.09 && $4 < 0.1) }' \
   && grep -q '^# only the soil particles' "$pp/bedTop/0/waveGauges.dat"; then
    pass "soil_functionObjects_phase (soil N, water N, bed top, top soil row: $got)"
else fail soil_functionObjects_phase "'$got' (want 200 200 0.1+-0.005 0.095+-0.005)"; fi

# forces with phase: the floor (tank Fy) carries the bed, whose share is
# the soil's: Fy(soil) within 10 % of -(rho g h_w + rho_s g h_s) L
# (L = 0.21 m: 21 floor particles of dp = 0.01 m), the water's share below 5 % of it, and the two add up to
# the whole to round-off
got=$(for ph in all soil water; do awk '!/^#/ { v = $3 } END { printf "%s ", v }' "$pp/load_$ph/0/forces.dat" 2>/dev/null; done)
if echo "$got" | awk '{ e = -(1000 * 9.81 * 0.1 + 1900 * 9.81 * 0.1) * 0.21; d = $1 - $2 - $3; if (d < 0) d = -d
        r = $2 / e - 1; if (r < 0) r = -r
        exit !(NF == 3 && d < 1e-9 * -$1 && r < 0.1 && $3 / $1 < 0.05) }'; then
    pass "soil_forces_phase (tank Fy all, soil, water [N/m]: $got)"
else fail soil_forces_phase "'$got' (want soil within 10 % of the bed's weight on the floor, water < 5 %, sum = all)"; fi

# --- solid model: runs, fields written, layer at rest, restart ---------------
setcase solid
if run && grep -q '^End' "$c/log.mpsFluid"; then pass soil_solid_run
else fail soil_solid_run "$(grep -A2 FATAL "$c/log.mpsFluid" | head -3 | tr '\n' ' ')"; fi
info=$("$ROOT/bin/vtuInfo" -case "$c" 0.1/fluid.vtu 2>/dev/null)
if echo "$info" | grep -q '^counts phase .*1:200' && echo "$info" | grep -q '^field acceleration Float64 3'
then pass soil_fields; else fail soil_fields "0.1/fluid.vtu lacks phase (200 soil) or acceleration"; fi
umax=$("$ROOT/bin/vtuInfo" -dump "$c/0.1/fluid.vtu" 2>/dev/null | awk '
    /^# x/ { for (i = 2; i <= NF; i++) k[$i] = i - 1; next } /^#/ || NF < 5 { next }
    $k["phase"] == 1 { u = sqrt($k["velocity_0"]^2 + $k["velocity_1"]^2); if (u > m) m = u }
    END { printf "%.5f", m / sqrt(9.81 * 0.2) }')
if awk -v u="$umax" 'BEGIN { exit !(u != "" && u < 0.02) }'; then pass "soil_solid_at_rest (max soil speed $umax sqrt(gh))"
else fail soil_solid_at_rest "max soil speed '$umax' sqrt(gh) (want < 0.02)"; fi

cp -r "$c" "$TMP/restart"; c="$TMP/restart"
rm -rf "$c/0.1" "$c/postProcessing" "$c/log.mpsFluid"
"$ROOT/bin/dictTool" -case "$c" system/controlDict -set startFrom=latestTime > /dev/null
(cd "$c" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1)
rows() { "$ROOT/bin/vtuInfo" -dump "$1" 2>/dev/null | awk '!/^#/ && NF > 10'; }
d=$(paste <(rows "$TMP/solid/0.1/fluid.vtu") <(rows "$c/0.1/fluid.vtu") | awk '
    { h = NF / 2; for (i = 1; i <= h; i++) { a = $i; b = $(i + h); s = (a < 0 ? -a : a) + (b < 0 ? -b : b)
        if (s > 0) { r = (a - b) / s; if (r < 0) r = -r; if (r > m) m = r } } } END { printf "%.3g", m + 0 }')
if [ -f "$c/0.1/fluid.vtu" ] && awk -v d="$d" 'BEGIN { exit !(d < 1e-9) }'; then pass "soil_restart (largest relative difference $d)"
else fail soil_restart "restart from 0.05 s differs from the continuous run by '$d'"; fi

# --- solid model, E5-02 at the tutorial's dp = 5 mm, 0-1 s --------------------
# (validation/soilLayer.sh, time average over 0.8-1 s: soil and water
# pressure L2 < 5 %, soil displacement < 0.5 dp; measured 0.021, 0.017,
# 0.26 dp; with `frictionLoad total`, the friction fed back, 0.156 and
# 0.243: doc/theory.md K0-10)
rm -rf "$TMP/solid1"; cp -r "$TUT" "$TMP/solid1"; c="$TMP/solid1"
got=$(run && MPSDEM_DIR="$ROOT" "$c/validation/soilLayer.sh" "$c" 0.2 2>/dev/null | tr '\n' ' ')
val() { echo "$got" | awk -v k=$1 '{ for (i = 1; i < NF; i++) if ($i == k) print $(i + 1) }'; }
if awk -v a="$(val L2soil)" -v b="$(val L2water)" -v d="$(val maxdisp)" \
       'BEGIN { exit !(a != "" && a < 0.05 && b < 0.05 && d < 0.5) }'; then pass "soil_E5-02_solid ($got)"
else fail soil_E5-02_solid "'$got' (want L2soil, L2water < 0.05, maxdisp < 0.5 dp)"; fi

# --- bad input ----------------------------------------------------------------
setcase nofile
rm "$c/constant/soilProperties"
if ! run && grep -q "constant/soilProperties: missing: the particles hold 200 soil" "$c/log.mpsFluid" 2>/dev/null \
   || grep -q "constant/soilProperties" "$c/log.genParticles" 2>/dev/null; then pass soil_missing_properties
else fail soil_missing_properties "no message naming constant/soilProperties"; fi
setcase badmodel
sed -i 's/^soilModel .*/soilModel soild;/' "$c/constant/soilProperties"
if ! run && grep -q "soilProperties:13.*did you mean 'solid'" "$c/log.mpsFluid"; then pass soil_bad_model
else fail soil_bad_model "$(grep -A2 FATAL "$c/log.mpsFluid" | head -3 | tr '\n' ' ')"; fi

# --- soilSlope, E5-03 (viscoplastic soil, doc/theory.md K.6): the
# deposit's angle within 5 deg of atan(mu) for mu = 0.3, 0.577, 1, at the
# tutorial's dp = 5 mm (12.9, 28.7, 48.1 deg; 45 s). dp = 10 mm is too
# coarse for the flank fit: 8 columns, one gap in them moved mu = 1 from
# 43.7 to 35.0 deg between two builds.
SL="$ROOT/tutorials/mpsFluid/soilSlope"
rm -rf "$TMP/slope"; cp -r "$SL" "$TMP/slope"
got=$(cd "$TMP/slope" && MPSDEM_DIR="$ROOT" ./Allrun 0.3 0.577 1 > /dev/null 2>&1 \
      && for mu in 0.3 0.577 1; do MPSDEM_DIR="$ROOT" validation/repose.sh mu$mu; done | tr '\n' ' ')
if echo "$got" | awk '{ if (NF != 15) exit 1
        for (k = 0; k < 3; k++) { d = $(5 * k + 2) - atan2($(5 * k + 1), 1) * 45 / atan2(1, 1)
                                  if (d > 5 || d < -5) exit 1 } }'; then
    pass "soil_slope_E5-03 (mu angle runout height umax: $got)"
else fail soil_slope_E5-03 "'$got' (want each angle within 5 deg of atan(mu))"; fi

# --- soilBlockIncline, E5-04 (viscoplastic soil): the middle of the block
# at rest at 25 deg (dx < 0.5 dp = 2.5 mm from 0.3 to 0.5 s) and sliding at
# 35 deg, mu = 0.577 (atan 30 deg; the bisection finds 28.4 deg)
BI="$ROOT/tutorials/mpsFluid/soilBlockIncline"
rm -rf "$TMP/incline"; cp -r "$BI" "$TMP/incline"
got=$(cd "$TMP/incline" && MPSDEM_DIR="$ROOT" ./Allrun 25 35 > /dev/null 2>&1 \
      && for th in 25 35; do MPSDEM_DIR="$ROOT" validation/slide.sh theta$th; done | tr '\n' ' ')
if echo "$got" | awk '{ exit !(NF == 6 && $2 < 0.0025 && $5 > 0.0025) }'; then
    pass "soil_incline_E5-04 (theta dx speed: $got)"
else fail soil_incline_E5-04 "'$got' (want dx < 2.5 mm at 25 deg, > 2.5 mm at 35 deg)"; fi

# --- damBreakMobileBed at dp = 10 mm, 0.3 s: the gate lifts, soil and
# water leave the reservoir; every soil particle kept; the bed made of
# water (MODEL water) has no soil function objects
MB="$ROOT/tutorials/mpsFluid/damBreakMobileBed"
rm -rf "$TMP/mb"; cp -r "$MB" "$TMP/mb"
"$ROOT/bin/dictTool" -case "$TMP/mb" system/particleDict -set dp=0.01 > /dev/null
"$ROOT/bin/dictTool" -case "$TMP/mb" system/controlDict -set endTime=0.3 -set writeInterval=0.1 > /dev/null
for m in solid liquid water; do
    if (cd "$TMP/mb" && MPSDEM_DIR="$ROOT" ./Allrun $m > /dev/null 2>&1); then
        d="$TMP/mb/${m}_1900"; [ $m = water ] && d="$TMP/mb/water"
        got=$(MPSDEM_DIR="$ROOT" "$MB/validation/soilFront.sh" "$d" | tail -1)
        nsoil=$(awk '!/^#/ { v = $2 } END { print v }' "$d/postProcessing/soilVolume/0/volume.dat" 2>/dev/null)
        if [ $m = water ]; then
            echo "$got" | awk '{ exit !($2 == "nan" && $5 > 0.4) }' && [ ! -d "$d/postProcessing/soilFront" ] \
                && pass "soil_mobileBed_water (t Xs Hs airborne Xw: $got)" \
                || fail soil_mobileBed_water "'$got' (want no soil, the water front past 0.4 m)"
        else
            echo "$got" | awk '{ exit !($2 > 0.35 && $5 > 0.35) }' && [ "$nsoil" = 450 ] \
                && pass "soil_mobileBed_$m (t Xs Hs airborne Xw: $got; soil particles $nsoil)" \
                || fail soil_mobileBed_$m "'$got', soil particles '$nsoil' (want both fronts past 0.35 m, 450 soil)"
        fi
    else
        fail soil_mobileBed_$m "Allrun $m failed"
    fi
done

setcase nosoil
sed -i 's/type    soil; .*/type    fluid;/; /surfaceHeight/d' "$c/system/particleDict"
"$ROOT/bin/dictTool" -case "$c" system/controlDict -new -set "functions/soilFront/type=front" -set "functions/soilFront/phase=soil" > /dev/null
if ! run && grep -q "controlDict:[0-9]*.*phase soil: the case has no soil particles" "$c/log.mpsFluid" \
   && [ ! -d "$c/0.05" ]; then pass soil_functionObject_noSoil
else fail soil_functionObject_noSoil "$(grep -A2 FATAL "$c/log.mpsFluid" | head -3 | tr '\n' ' ')"; fi

[ "$fails" -eq 0 ]
