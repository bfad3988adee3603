#!/usr/bin/env bash
# mpsDemSettling.sh — quick tandem run of tutorials/mpsDem/singleGrainSettling
# (mpsFluid + demSolid through the coupling channel, Model B, 0.35 s):
#   both programs reach End, the channel segment is gone afterwards;
#   E1-14 over 0.2-0.35 s (couplingForces function object): the mean
#   F^d/eps_k balances the submerged weight within 3 % and the mean slip
#   is within 3 % of the balance slip 0.3357 m/s at eps_k = 0.9883 (over
#   0.2-0.6 s in the tutorial: +0.43 % and +0.3 %; the short window carries
#   the MPS velocity noise); lab-frame speed within 15 % of 0.343 m/s;
#   the couplingForces function object gives the buoyancy V rho_f g (1e-6);
#   a restart from 0.02 s gives the continuous run's 0.04 s files exactly;
#   a case without system/couplingDict runs demSolid alone (no channel)
#   and its dem.vtu has the 5 grain fields only, where the coupled run's
#   dem.vtu and fluid.vtu have the coupling fields (couple_fluid.h, couple_dem.h).
# MPSFLUID / DEMSOLID override the programs (default bin/).
NAME=mpsDemSettling
. "$(dirname "$0")/lib/tandem.sh"
TUT="$ROOT/tutorials/mpsDem/singleGrainSettling"
c="$TMP/case"
cp -r "$TUT" "$c"
sed -i 's/^endTime .*/endTime 0.35;/; s/^timeout .*/timeout 30;/' \
    "$c/system/controlDict" "$c/system/couplingDict"
echo "channel mpsdem-settling-test-$$;" >> "$c/system/couplingDict"
(cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) \
    || { fail mpsDemSettling "genParticles failed"; exit 1; }
if run_tandem "$c" 300 && grep -q 'exchanges' "$c/log.mpsFluid"; then
    pass mpsDemSettling_tandem
    if [ -s "$c/postProcessing/usedParameters/mpsFluid" ] \
       && [ -s "$c/postProcessing/usedParameters/demSolid" ]; then
        pass mpsDemSettling_usedParametersOfBothPrograms
    else
        fail mpsDemSettling_usedParametersOfBothPrograms "$(ls "$c/postProcessing/usedParameters" 2>&1)"
    fi
else
    fail mpsDemSettling_tandem "exit $rf/$rd: $(fatal_of "$c")"
    exit 1
fi
[ ! -e "/dev/shm/mpsdem-settling-test-$$" ] && pass mpsDemSettling_channel_removed \
    || fail mpsDemSettling_channel_removed "/dev/shm/mpsdem-settling-test-$$ left"
out=$("$c/validation/terminalVelocity.sh" 0.2)
echo "$out" | sed 's/^/    /'
m=$(echo "$out" | awk '/^grain speed/ { print $7 }')
bal=$(echo "$out" | awk '/^mean F\^d/ { v = $(NF-1); gsub(/[(+]/, "", v); print v }')
slip=$(echo "$out" | awk '/^mean slip/ { print $6 }')
awk -v b="$bal" 'BEGIN { exit !(b != "" && b < 3 && b > -3) }' \
    && pass "mpsDemSettling_dragBalance ${bal} %" \
    || fail mpsDemSettling_dragBalance "mean F^d/eps_k vs submerged weight: ${bal} % (3 %)"
awk -v s="$slip" 'BEGIN { d = s / 0.3357 - 1; exit !(s > 0 && d < 0.03 && d > -0.03) }' \
    && pass "mpsDemSettling_slip $slip m/s vs 0.3357" \
    || fail mpsDemSettling_slip "mean slip $slip m/s, balance 0.3357 m/s (3 %)"
awk -v m="$m" 'BEGIN { d = m / 0.343 - 1; exit !(d < 0.15 && d > -0.15) }' \
    && pass mpsDemSettling_absolute || fail mpsDemSettling_absolute "$m m/s vs 0.343 (15 %)"
# couplingForces function object: Model B buoyancy is exactly V rho_f g
f="$c/postProcessing/grain/0/couplingForces.dat"
awk '!/^#/ { n++; b = $6 } END { V = 4 / 3 * 3.14159265358979 * 0.00135^3
     exit !(n > 10 && (b / (V * 1000 * 9.81) - 1)^2 < 1e-12) }' "$f" 2>/dev/null \
    && pass mpsDemSettling_buoyancy \
    || fail mpsDemSettling_buoyancy "couplingForces.dat: $(tail -1 "$f" 2>&1)"
# restart: 0 -> 0.04 s continuous, then 0.02 -> 0.04 s from the written
# state; porosity and pairs are rebuilt, and the result must be identical
r="$TMP/restart"
cp -r "$TUT" "$r"
sed -i 's/^endTime .*/endTime 0.04;/; s/^writeInterval .*/writeInterval 0.02;/' "$r/system/controlDict"
sed -i 's/^timeout .*/timeout 30;/' "$r/system/couplingDict"
echo "channel mpsdem-settling-restart-$$;" >> "$r/system/couplingDict"
if (cd "$r" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) && run_tandem "$r" 120 1 \
   && mv "$r/0.04" "$r/continuous" \
   && sed -i 's/^startFrom .*/startFrom latestTime;/' "$r/system/controlDict" \
   && run_tandem "$r" 120 2 && cmp -s "$r/continuous/fluid.vtu" "$r/0.04/fluid.vtu" \
   && cmp -s "$r/continuous/dem.vtu" "$r/0.04/dem.vtu"; then
    pass mpsDemSettling_restart_identical
else
    fail mpsDemSettling_restart_identical "restart from 0.02 s differs from the continuous run at 0.04 s (or a run failed)"
fi
# uncoupled: the same case without couplingDict, demSolid alone (the
# coupling-only function objects are switched off with 'cloud none')
rm "$c/system/couplingDict"
sed -i 's/cloud  *dem;/cloud none;/' "$c/system/controlDict"
sed -i 's/^endTime .*/endTime 0.01;/' "$c/system/controlDict"
if (cd "$c" && timeout 60 "$DEMSOLID" > log.demSolid.alone 2>&1) \
   && ! grep -qi 'channel\|coupling' "$c/log.demSolid.alone"; then
    pass mpsDemSettling_uncoupled
else
    fail mpsDemSettling_uncoupled "demSolid alone: $(tail -3 "$c/log.demSolid.alone" | tr '\n' ' ')"
fi
# coupling fields (couple_fluid.h, couple_dem.h) in the coupled output only: the
# standalone run rewrote 0.01/dem.vtu without them
cf=$("$ROOT/bin/vtuInfo" -case "$c" 0.35/dem.vtu 0.35/fluid.vtu 2>&1 \
     | grep -c '^field \(porosity\|fluidVelocity\|slipVelocity\|drag\|buoyancy\|reaction\) ')
sf=$("$ROOT/bin/vtuInfo" -case "$c" 0.01/dem.vtu 2>&1 | grep -c '^field ')
[ "$cf" = 7 ] && [ "$sf" = 5 ] \
    && pass mpsDemSettling_couplingFieldsOnlyCoupled \
    || fail mpsDemSettling_couplingFieldsOnlyCoupled "coupled files: $cf of 7 coupling fields; standalone dem.vtu: $sf fields (5)"
exit $((fails > 0))
