#!/usr/bin/env bash
# pairSkin.sh — `pairSkin` in system/couplingDict (Verlet skin of the
# grain-particle pairs, src/couplingMps/couple_fluid.c find_pairs) on the
# quick 2-D sedimentation set-up of mpsDemRestart.sh (15 beads, dp 5 mm,
# Model B, 0.2 s of 4e-4 s steps):
#   skin_searches   pairSkin 0 searches twice per exchange; pairSkin 0.1
#                   at most once per 4 exchanges (measured 105 in 500:
#                   when the MPS list, skin 0.5 dp, renumbers); before
#                   2026-11-28 it searched at least once per exchange
#   skin_same       the beads' positions with 0.1 equal those with 0
#                   within 1e-9 m and their velocities within 1e-6 m/s
#                   (measured 4.4e-12 m, 2.8e-10 m/s: the same pairs
#                   within r_e,s, summed in another order)
NAME=pairSkin
. "$(dirname "$0")/lib/tandem.sh"
make_case()   # DIR SKIN
{
    local c="$1"
    case_beads_2d "$c"
    cat > "$c/system/controlDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
startFrom startTime; startTime 0; endTime 0.2; deltaT 4e-4; adjustTimeStep no;
writeControl runTime; writeInterval 0.1; writeFormat ascii;
functions
{
    state { type grainState; cloud dem; ids (0 7 14); writeControl timeStep; writeInterval 25; }
}
EOD
    sed -i "s/^timeout .*/timeout 20;/; s/^pairSkin .*/pairSkin $2;/" "$c/system/couplingDict"
    echo "channel mpsdem-pairskin-$$-${2/./};" >> "$c/system/couplingDict"
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1)
}
for sk in 0 0.1; do
    make_case "$TMP/s$sk" $sk || { fail pairSkin_setup "genParticles failed ($sk)"; exit 1; }
    run_tandem "$TMP/s$sk" 120 || { fail "pairSkin_run_$sk" "exit $rf/$rd: $(fatal_of "$TMP/s$sk")"; exit 1; }
done
counts() { awk '/^Coupling: [0-9]+ exchanges/ { print $2, $4 }' "$1/log.mpsFluid"; }
read -r n0 s0 <<< "$(counts "$TMP/s0")"
read -r n1 s1 <<< "$(counts "$TMP/s0.1")"
echo "    exchanges / pair searches: pairSkin 0: $n0 / $s0, pairSkin 0.1: $n1 / $s1"
awk -v n0="$n0" -v s0="$s0" -v n1="$n1" -v s1="$s1" \
    'BEGIN { exit !(n0 > 100 && s0 >= 2 * n0 && n1 == n0 && s1 > 0 && 4 * s1 <= n1) }' \
    && pass pairSkin_searches || fail pairSkin_searches "skin 0: $s0 of $n0, skin 0.1: $s1 of $n1"
f=postProcessing/state/0/grainState.dat
if [ -s "$TMP/s0/$f" ] && [ -s "$TMP/s0.1/$f" ]; then
    # columns per grain: x y z, vx vy vz, wx wy wz
    d=$(paste "$TMP/s0/$f" "$TMP/s0.1/$f" | awk '!/^#/ { h = NF / 2; n++
            for (k = 2; k <= h; k++) { e = $k - $(k + h); if (e < 0) e = -e
                q = int((k - 2) % 9 / 3); if (e > m[q]) m[q] = e } }
        END { printf "%d %.3g %.3g", n, m[0], m[1] }')
    echo "    grain state rows, largest difference of position [m], velocity [m/s]: $d"
    awk -v d="$d" 'BEGIN { split(d, a, " "); exit !(a[1] >= 5 && a[2] <= 1e-9 && a[3] <= 1e-6) }' \
        && pass pairSkin_same || fail pairSkin_same "rows, position and velocity difference: $d"
else
    fail pairSkin_same "no $f"
fi
exit $((fails > 0))
