#!/usr/bin/env bash
# mpsDemSedimentation2D.sh — quick 2-D version of the sedimentation case
# (METHODS.md A.12.1, E1-16, E1-18): 15 beads (d = 5 mm, 5 x 3, centres
# 10 mm apart) released in a 0.05 m wide tank of still water 0.1 m deep,
# dp = 5 mm, 0.5 s, Model A and Model B in tandem (~2 s each):
#   both run to End without escapes;
#   Model B (E1-16): grain kinetic energy at 0.5 s <= 1 % of its peak
#   (measured 0.47 %), |total drag| <= 2 % of the submerged weight
#   (measured 0.6 %), total buoyancy = N V rho_f g to 1e-8 (9 digits written);
#   Model A: the pressure-gradient force (A0-14) within 10 % of the
#   buoyancy (measured +4 %), kinetic energy at 0.5 s <= 1 % of its peak
#   (measured 0.39 %: the paper's late growth of Model A's energy, E1-18,
#   does not appear in this coarse quick case).
# Looser than the paper's touching beads on purpose: with the fluid lattice
# filling the pores (A0-16) a dense 2-D bed starts at n ~ 1.4 n0 and throws
# the water out of the tank.
# MPSFLUID / DEMSOLID override the programs (default bin/).
NAME=mpsDemSedimentation2D
. "$(dirname "$0")/lib/tandem.sh"
for model in A B; do
    c="$TMP/$model"
    mkdir -p "$c/system" "$c/constant" "$c/0"
    cp "$ROOT"/system/{couplingDict,mpsSchemes,mpsSolution,demSolution} "$c/system/"
    cp "$ROOT"/constant/{demProperties,transportProperties} "$c/constant/"
    cp "$ROOT/tutorials/mpsFluid/damBreak2D/constant/g" "$c/constant/"
    cat > "$c/system/particleDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object particleDict; }
dimension    2;
dp           0.005;
kernelRadius 3.1;
wallLayers   auto;
regions
(
    tank   { type tankWall; shape box; min (0 0 0); max (0.05 0.15 0); open (ymax); }
    water  { type fluid; shape box; min (0 0 0); max (0.05 0.1 0); hydrostaticPressure yes; }
    beads  { type grains; shape box; min (0.0025 0.0105 0); max (0.0475 0.0405 0);
             diameter 0.005; lattice cubic; spacing 0.01; }
);
EOD
    cat > "$c/system/controlDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
startFrom startTime; startTime 0; endTime 0.5; deltaT 4e-4; adjustTimeStep no;
writeControl runTime; writeInterval 0.1; writeFormat ascii;
functions
{
    energy { type kineticEnergy; cloud dem; writeControl timeStep; writeInterval 5; }
    forces { type couplingForces; cloud dem; writeControl timeStep; writeInterval 5; }
}
EOD
    sed -i "s/^model .*/model $model;/; s/^timeout .*/timeout 30;/" "$c/system/couplingDict"
    echo "channel mpsdem-sed2d-$model-$$;" >> "$c/system/couplingDict"
    (cd "$c" && "$ROOT/bin/genParticles" > log.genParticles 2>&1) \
        || { fail "sedimentation2D_$model" "genParticles failed"; continue; }
    run_tandem "$c"; ok=$?
    esc=$(grep -o 'escaped [0-9]*' "$c/log.mpsFluid" | tail -1 | awk '{ print $2 }')
    if [ $ok -ne 0 ] || [ "$esc" != 0 ]; then
        fail "sedimentation2D_${model}_run" "exit $rf/$rd, escaped $esc: $(fatal_of "$c")"
        continue
    fi
    pass "sedimentation2D_${model}_run"
    ke=$(awk '!/^#/ { if ($4 > pk) pk = $4; last = $4 } END { print last / pk }' \
         "$c/postProcessing/energy/0/kineticEnergy.dat")
    awk -v r="$ke" 'BEGIN { exit !(r >= 0 && r <= 0.01) }' \
        && pass "sedimentation2D_${model}_kineticEnergy E(0.5 s)/E_peak = $ke" \
        || fail "sedimentation2D_${model}_kineticEnergy" "E(0.5 s)/E_peak = $ke (<= 1 %)"
    # last row: time drag(3) pressure(3) slip eps wet; 15 beads of d = 5 mm
    read -r dr pr <<< "$(awk '!/^#/ { l = $0 } END { split(l, a)
        V = 15 * 4 / 3 * 3.14159265358979 * 0.0025^3
        printf "%.6g %.9g", sqrt(a[2]^2 + a[3]^2) / (1500 * V * 9.81), a[6] / (1000 * V * 9.81) - 1 }' \
        "$c/postProcessing/forces/0/couplingForces.dat")"
    if [ $model = B ]; then
        awk -v d="$dr" 'BEGIN { exit !(d <= 0.02) }' \
            && pass "sedimentation2D_B_drag |F_d|/W' = $dr" \
            || fail sedimentation2D_B_drag "|F_d|/W' = $dr (<= 2 %)"
        awk -v p="$pr" 'BEGIN { exit !(p < 1e-8 && p > -1e-8) }' \
            && pass "sedimentation2D_B_buoyancy exact ($pr)" \
            || fail sedimentation2D_B_buoyancy "total buoyancy off by $pr"
    else
        awk -v p="$pr" 'BEGIN { exit !(p < 0.1 && p > -0.1) }' \
            && pass "sedimentation2D_A_pressureForce vs buoyancy $pr" \
            || fail sedimentation2D_A_pressureForce "relative difference $pr (10 %)"
    fi
done
exit $((fails > 0))
