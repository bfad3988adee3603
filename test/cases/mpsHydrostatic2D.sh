#!/usr/bin/env bash
# mpsHydrostatic2D.sh — quick checks of mpsFluid on the 2-D still-water
# tutorial (tutorials/mpsFluid/hydrostaticTank2D, 400 fluid particles, its
# Allrun: a relaxed start, mpsFluid -relax 10, then 1 s; ~25 s of CPU):
#   E1-08 (2-D quick version, the tutorial's still-water options):
#         L2 of the time-averaged pressure over the last 0.2 s < 1.5 %,
#         max fluid speed < 1 % sqrt(g h) (the E1-08 target; measured
#         0.87 % and 0.45 %)
#   E1-07: deep particles flagged as surface < 0.5 % (measured 0); in all
#         50 snapshots the surface flags are the top layer of the relaxed
#         water: 18-21 particles, none with a fluid particle above it,
#         no gap wider than 2 dp (measured 18-21, 0, 1.6 dp)
#   -relax: the relaxed 0/fluid.vtu is at rest (every velocity 0, time 0),
#         keeps every particle, and nothing else is written (no .pvd
#         entry, no time directory, no function-object output); refused
#         with a clear message for a coupled case, a moving wall and a bad
#         time, leaving 0/ untouched
#   volume: no particle lost, run ends with End; probe and wave gauge
#   restart: 0 -> 0.1 s in one run equals 0 -> 0.05 s + restart to 0.1 s
#            to round-off (1e-9 relative; measured 3e-14 relative)
#   bad input: unknown kernel (file:line, valid names), unstable deltaT
#   refused before the first step, PPE not converged (stops, state written
#   to failed.<t>/, not to a time directory),
#   missing fluid.vtu
# one thread (lib/case.sh): bit-for-bit restart comparison; tiny case
NAME=mpsHydrostatic2D; . "$(dirname "$0")/lib/case.sh"
need_bins mpsFluid genParticles vtuInfo dictTool
TUT="$ROOT/tutorials/mpsFluid/hydrostaticTank2D"
setcase() { rm -rf "$TMP/$1"; cp -r "$TUT" "$TMP/$1"; c="$TMP/$1"; }
set_entry() { "$ROOT/bin/dictTool" -case "$c" "$1" -set "$2=$3" >/dev/null; }

# --- accuracy (the tutorial's Allrun: genParticles, -relax 10, the run) ---
setcase run
set_entry system/controlDict writeInterval 0.02
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 \
         && "$ROOT/bin/mpsFluid" -relax 10 > log.mpsFluid.relax 2>&1)
rc=$?
# the relaxed start: at rest at time 0, every particle kept, nothing else
# written by the relaxation (the lattice's 0/ and the .pvd of genParticles)
rel=$("$ROOT/bin/vtuInfo" -dump "$c/0/fluid.vtu" 2>/dev/null | awk '
    !/^#/ && NF > 10 { n++; if ($4 == 0) nf++; if ($6 != 0 || $7 != 0 || $8 != 0) moving++ }
    END { print n + 0, nf + 0, moving + 0 }')
tv=$("$ROOT/bin/vtuInfo" "$c/0/fluid.vtu" 2>/dev/null | awk '$1 == "time" { print $2 }')
extra=$(cd "$c" && ls -d [0-9]* postProcessing/*/ 2>/dev/null | grep -v '^0$' | grep -v usedParameters | tr '\n' ' ')
if [ $rc -eq 0 ] && grep -q '^Relaxed state (20000 steps)' "$c/log.mpsFluid.relax" \
   && [ "$rel" = "752 400 0" ] && [ "$tv" = 0 ] && [ -z "$extra" ] \
   && [ "$(grep -c 'DataSet' "$c/fluid.pvd")" = 1 ]; then
    pass mpsFluid_relax
else
    fail mpsFluid_relax "rc $rc, particles/fluid/moving '$rel' (752 400 0), time '$tv', written besides 0/: '$extra'"
fi
(cd "$c" && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1)
if [ $? -ne 0 ] || ! grep -q '^End' "$c/log.mpsFluid"; then
    fail hydrostatic2D_run "mpsFluid failed: $(grep -A2 FATAL "$c/log.mpsFluid" | head -3 | tr '\n' ' ')"
else
    pass hydrostatic2D_run
    out=$("$TUT/validation/hydrostatic.sh" "$c" 0.2)
    val() { echo "$out" | awk -v k=$1 '$1 == k { print $2 }'; }
    echo "    $(echo $out)"
    awk -v v=$(val L2) 'BEGIN { exit !(v < 0.015) }' && pass hydrostatic2D_L2 \
        || fail hydrostatic2D_L2 "time-averaged pressure L2 $(val L2) >= 0.015"
    awk -v v=$(val umax_rel) 'BEGIN { exit !(v < 0.01) }' && pass hydrostatic2D_umax \
        || fail hydrostatic2D_umax "max |u| / sqrt(gh) $(val umax_rel) >= 0.01"
    awk -v v=$(val deepfs) 'BEGIN { exit !(v < 0.005) }' && pass hydrostatic2D_freeSurface \
        || fail hydrostatic2D_freeSurface "deep particles flagged $(val deepfs)"
    # E1-07 on relaxed water, whose top is no lattice row: in every
    # snapshot the flagged particles are exposed (no fluid particle above
    # one within dp/2 horizontally: none is interior), 18 to 21 of them
    # (20 columns of dp), leaving no hole in the surface (largest gap
    # between neighbouring flagged particles or to a wall <= 2 dp)
    top=$(cd "$c" && for t in $(ls -d [0-9]* | sort -g | tail -n +2); do
        "$ROOT/bin/vtuInfo" -dump "$t/fluid.vtu" 2>/dev/null | awk '!/^#/ && NF > 14 && $4 == 0 { print $1, $2, $15 }' |
        awk -v t=$t -v dp=0.005 -v lo=0 -v hi=0.1 '{ x[NR] = $1; y[NR] = $2; f[NR] = $3 }
            END { for (i = 1; i <= NR; i++) if (f[i] == 1) { nf++; xs[nf] = x[i]
                      for (j = 1; j <= NR; j++) if (y[j] > y[i] && (x[j] - x[i])^2 < dp * dp / 4) { inner++; break } }
                  for (i = 2; i <= nf; i++) { v = xs[i]; k = i - 1
                      while (k > 0 && xs[k] > v) { xs[k + 1] = xs[k]; k-- } xs[k + 1] = v }
                  gap = nf ? xs[1] - lo : hi - lo; if (nf && hi - xs[nf] > gap) gap = hi - xs[nf]
                  for (i = 2; i <= nf; i++) if (xs[i] - xs[i - 1] > gap) gap = xs[i] - xs[i - 1]
                  if (nf < 18 || nf > 21 || inner || gap > 2 * dp)
                      printf "t=%s: %d flagged, %d interior, gap %.2f dp; ", t, nf, inner, gap / dp }'
    done)
    [ -z "$top" ] && pass hydrostatic2D_topLayer || fail hydrostatic2D_topLayer "$top"
    # probes and wave gauge over the last 0.2 s: bottom probe at y = 0.0025
    # against rho g (h - y) = 956.6 Pa within 1 % (measured 958.6); surface
    # at h = 0.1 m within dp/4 (measured 0.10086: the gauge reads the
    # highest particle of its column + dp/2, and the top particles of the
    # relaxed water sit at different heights, 0.0962-0.0985 m at 0.5 s)
    pb=$(awk '!/^#/ && $1 >= 0.8 { s += $2; n++ } END { print s / n }' "$c/postProcessing/bottom/0/probes.dat")
    hg=$(awk '!/^#/ && $1 >= 0.8 { s += $2; n++ } END { print s / n }' "$c/postProcessing/level/0/waveGauges.dat")
    echo "    bottom probe $pb Pa, wave gauge $hg m"
    awk -v p=$pb 'BEGIN { e = (p - 956.6) / 956.6; exit !(e < 0.01 && e > -0.01) }' \
        && pass hydrostatic2D_probe || fail hydrostatic2D_probe "bottom pressure $pb Pa (956.6 expected)"
    awk -v h=$hg 'BEGIN { exit !(h > 0.09875 && h < 0.10125) }' \
        && pass hydrostatic2D_gauge || fail hydrostatic2D_gauge "surface at $hg m (0.1 expected)"
    vol="$c/postProcessing/volume/0/volume.dat"
    if awk '!/^#/ { if ($2 != 400 || $4 != 0 || $5 != 0) bad = 1; n++ } END { exit !(n > 10 && !bad) }' "$vol"; then
        pass hydrostatic2D_volume
    else
        fail hydrostatic2D_volume "fluid count changed or particles escaped ($vol)"
    fi
fi

# --- restart ---------------------------------------------------------------
dumpsorted() { "$ROOT/bin/vtuInfo" -dump "$1" 2>/dev/null | awk '!/^#/ && NF > 10' | sort -k13,13n; }
setcase cont
set_entry system/controlDict endTime 0.1
set_entry system/controlDict writeInterval 0.05
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1)
setcase rest
set_entry system/controlDict endTime 0.05
set_entry system/controlDict writeInterval 0.05
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1)
set_entry system/controlDict endTime 0.1
set_entry system/controlDict startFrom latestTime
(cd "$c" && "$ROOT/bin/mpsFluid" > log.mpsFluid.restart 2>&1)
if [ -f "$TMP/cont/0.1/fluid.vtu" ] && [ -f "$TMP/rest/0.1/fluid.vtu" ]; then
    d=$(paste <(dumpsorted "$TMP/cont/0.1/fluid.vtu") <(dumpsorted "$TMP/rest/0.1/fluid.vtu") |
        awk '{ n = NF / 2; for (k = 1; k <= n; k++) { a = $(k + n); e = ($k - a) / (1 + (a < 0 ? -a : a)); if (e < 0) e = -e; if (e > m) m = e } } END { print m + 0 }')
    # round-off: dt is shortened by ulps to land on write times
    awk -v d=$d 'BEGIN { exit !(d < 1e-9) }' && pass hydrostatic2D_restart \
        || fail hydrostatic2D_restart "restarted run differs from the continuous one by $d (relative)"
else
    fail hydrostatic2D_restart "missing 0.1/fluid.vtu ($(grep -h FATAL -A2 "$TMP"/*/log.mpsFluid* | head -3 | tr '\n' ' '))"
fi

# --- bad input -------------------------------------------------------------
setcase bad
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
cp "$c/system/mpsSchemes" "$c/system/mpsSchemes.orig"
sed -i 's/^kernel .*/kernel           zhang2041;/' "$c/system/mpsSchemes"
out=$(cd "$c" && "$ROOT/bin/mpsFluid" 2>&1); rc=$?
if [ $rc -ne 0 ] && echo "$out" | grep -q "mpsSchemes:[0-9]*:.*zhang2041.*zhang2014" && [ ! -d "$c/0.1" ]; then
    pass mpsFluid_badKernel
else
    fail mpsFluid_badKernel "rc $rc: $(echo "$out" | grep -A2 FATAL | tr '\n' ' ')"
fi
cp "$c/system/mpsSchemes.orig" "$c/system/mpsSchemes"
sed -i 's/^deltaT .*/deltaT 0.01;/' "$c/system/controlDict"
out=$(cd "$c" && "$ROOT/bin/mpsFluid" 2>&1); rc=$?
if [ $rc -ne 0 ] && echo "$out" | grep -q "Courant" && ! echo "$out" | grep -q "^Time ="; then
    pass mpsFluid_unstableDeltaT
else
    fail mpsFluid_unstableDeltaT "rc $rc: $(echo "$out" | grep -A2 FATAL | tr '\n' ' ')"
fi
sed -i 's/^deltaT .*/deltaT 5e-4;/' "$c/system/controlDict"
sed -i 's/^    maxIter .*/    maxIter 2;/' "$c/system/mpsSolution"
out=$(cd "$c" && "$ROOT/bin/mpsFluid" 2>&1); rc=$?
if [ $rc -ne 0 ] && echo "$out" | grep -q "step 0: the pressure Poisson equation" \
   && [ -f "$c/failed.0.0005/fluid.vtu" ] && [ ! -e "$c/0.0005" ]; then
    pass mpsFluid_ppeNotConverged
else
    fail mpsFluid_ppeNotConverged "rc $rc: $(echo "$out" | grep -A2 FATAL | tr '\n' ' ')"
fi
sed -i 's/^    maxIter .*/    maxIter 1000;/' "$c/system/mpsSolution"
# -relax refused before any step, 0/fluid.vtu untouched: a bad time, a
# coupled case, a wall that moves
sum0=$(md5sum < "$c/0/fluid.vtu")
relax_refused() {  # NAME PATTERN ARG
    out=$(cd "$c" && "$ROOT/bin/mpsFluid" -relax "$3" 2>&1); rc=$?
    if [ $rc -ne 0 ] && echo "$out" | grep -q "$2" && ! echo "$out" | grep -q "^Time =" \
       && [ "$(md5sum < "$c/0/fluid.vtu")" = "$sum0" ]; then
        pass "$1"
    else
        fail "$1" "rc $rc: $(echo "$out" | grep -A2 FATAL | tr '\n' ' ')"
    fi
}
relax_refused mpsFluid_relaxBadTime "-relax ten: the relaxation time must be a number > 0" ten
relax_refused mpsFluid_relaxNegativeTime "-relax -1: the relaxation time must be a number > 0" -1
printf 'FoamFile { object couplingDict; }\ncoupled yes;\n' > "$c/system/couplingDict"
relax_refused mpsFluid_relaxCoupled "couplingDict: -relax runs mpsFluid alone" 1
rm "$c/system/couplingDict"
cp "$c/system/particleDict" "$c/system/particleDict.orig"
sed -i 's|open    (ymax);.*|open    (ymax); removeAt 0.5;|' "$c/system/particleDict"
relax_refused mpsFluid_relaxMovingWall "particleDict: -relax needs walls that stay put" 1
cp "$c/system/particleDict.orig" "$c/system/particleDict"
rm -f "$c/0/fluid.vtu"
out=$(cd "$c" && "$ROOT/bin/mpsFluid" 2>&1); rc=$?
if [ $rc -ne 0 ] && echo "$out" | grep -q "fluid.vtu"; then
    pass mpsFluid_missingCloud
else
    fail mpsFluid_missingCloud "rc $rc: $(echo "$out" | grep -A2 FATAL | tr '\n' ' ')"
fi
exit $((fails > 0))
