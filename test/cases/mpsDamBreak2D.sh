#!/usr/bin/env bash
# mpsDamBreak2D.sh — the coarsest Martin & Moyce dam break
# (tutorials/mpsFluid/damBreak2D, dp = a/10, 200 fluid particles, ~1 s):
#   runs to End; fluid count conserved;
#   surge front RMS (no time shift) < 0.20 (measured 0.152);
#   column height RMS < 0.05 (measured 0.027).
NAME=damBreak2D; . "$(dirname "$0")/lib/case.sh"
need_bins mpsFluid
TUT="$ROOT/tutorials/mpsFluid/damBreak2D"
[ -d "$ROOT/data/martin_moyce_1952" ] || { fail damBreak2D "data missing"; exit 1; }
c="$TMP/case"
cp -r "$TUT" "$c"
if (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1 \
    && "$ROOT/bin/mpsFluid" > log.mpsFluid 2>&1) && grep -q '^End' "$c/log.mpsFluid"; then
    pass damBreak2D_run
else
    fail damBreak2D_run "$(grep -A2 FATAL "$c/log.mpsFluid" | head -3 | tr '\n' ' ')"
    exit 1
fi
out=$("$TUT/validation/compare.sh" "$c")
echo "    $(echo $out)"
val() { echo "$out" | awk -v k=$1 '$1 == k { print $2 }'; }
awk -v v=$(val rmsZ) -v n=$(val nZ) 'BEGIN { exit !(v >= 0 && v < 0.20 && n >= 12) }' \
    && pass damBreak2D_front || fail damBreak2D_front "rms Z $(val rmsZ) over $(val nZ) points"
awk -v v=$(val rmsH) -v n=$(val nH) 'BEGIN { exit !(v >= 0 && v < 0.05 && n >= 10) }' \
    && pass damBreak2D_column || fail damBreak2D_column "rms H $(val rmsH) over $(val nH) points"
if awk '!/^#/ { if ($2 != 200 || $4 != 0 || $5 != 0) bad = 1; n++ } END { exit !(n > 2 && !bad) }' \
       "$c/postProcessing/volume/0/volume.dat"; then
    pass damBreak2D_volume
else
    fail damBreak2D_volume "fluid particle count changed"
fi
exit $((fails > 0))
